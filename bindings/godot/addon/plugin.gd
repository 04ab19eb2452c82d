@tool
extends EditorPlugin
## libsmg's classes are registered by the GDExtension (smg.gdextension),
## not by this plugin. Enabled, it says plainly when the extension did not
## load, e.g. on a platform the addon ships no library for.


func _enter_tree() -> void:
	if not ClassDB.class_exists("SmgCharacter"):
		push_error(("libsmg: the extension is not loaded on %s %s; this addon ships libraries for "
			+ "linux.x86_64 and windows.x86_64 (see addons/libsmg/smg.gdextension)")
			% [OS.get_name(), Engine.get_architecture_name()])
