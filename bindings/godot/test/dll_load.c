/* dll_load.c DLL - a Windows program (run under Wine by
 * test/addon_test.sh) that loads the extension DLL as Godot does on
 * Windows - LoadLibrary, then the entry symbol smg_godot_init - and calls
 * the entry twice with a stand-in for Godot's get_proc_address:
 *   - one that knows every interface function (placeholders that are never
 *     called): the entry must accept and fill in its initialization
 *     callbacks at the SCENE level;
 *   - one that knows none (an incompatible Godot): the entry must refuse.
 * Prints "dll: N passed, M failed"; exits 0 only when all passed. */
#include <stdio.h>
#include <string.h>
#include <windows.h>

#include "gdextension_interface.h"

static int passed, failed, asked;

static void check(int ok, const char *what) {
	printf("%s %s\n", ok ? "PASS" : "FAIL", what);
	if (ok) passed++;
	else failed++;
}

static void placeholder(void) {
}

static GDExtensionInterfaceFunctionPtr knows_all(const char *name) {
	(void)name;
	asked++;
	return placeholder;
}

static GDExtensionInterfaceFunctionPtr knows_none(const char *name) {
	(void)name;
	return NULL;
}

int main(int argc, char **argv) {
	if (argc != 2) {
		fprintf(stderr, "usage: dll_load DLL\n");
		return 2;
	}
	HMODULE dll = LoadLibraryA(argv[1]);
	check(dll != NULL, "LoadLibrary loads the DLL (its imports resolve)");
	if (!dll) {
		printf("LoadLibrary error %lu\n", (unsigned long)GetLastError());
		printf("dll: %d passed, %d failed\n", passed, failed + 1);
		return 1;
	}
	GDExtensionInitializationFunction entry;
	FARPROC f = GetProcAddress(dll, "smg_godot_init");
	memcpy(&entry, &f, sizeof entry);
	check(entry != NULL, "GetProcAddress finds smg_godot_init");
	if (entry) {
		GDExtensionInitialization init;
		memset(&init, 0, sizeof init);
		GDExtensionBool ok = entry(knows_all, (GDExtensionClassLibraryPtr)&init, &init);
		check(ok && init.initialize && init.deinitialize &&
			init.minimum_initialization_level == GDEXTENSION_INITIALIZATION_SCENE,
			"the entry accepts a Godot that has every interface function");
		printf("  (%d interface functions looked up)\n", asked);
		memset(&init, 0, sizeof init);
		check(!entry(knows_none, (GDExtensionClassLibraryPtr)&init, &init),
			"the entry refuses a Godot that lacks them");
	}
	check(FreeLibrary(dll) != 0, "FreeLibrary unloads it");
	printf("dll: %d passed, %d failed\n", passed, failed);
	return failed != 0;
}
