/* nodeepbind.c - LD_PRELOAD shim for the AddressSanitizer run of the Godot
 * test (make test-godot-asan): Godot opens GDExtensions with RTLD_DEEPBIND,
 * which the sanitizer runtime refuses, so this dlopen drops that flag and
 * passes everything else on. Test tooling only; never part of the product. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stddef.h>

void *dlopen(const char *file, int flags) {
	static void *(*real_dlopen)(const char *, int);
	if (!real_dlopen) {
		void *sym = dlsym(RTLD_NEXT, "dlopen");
		*(void **)&real_dlopen = sym;
	}
	return real_dlopen ? real_dlopen(file, flags & ~RTLD_DEEPBIND) : NULL;
}
