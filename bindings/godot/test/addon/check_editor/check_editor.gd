@tool
extends EditorPlugin
## make test-godot-addon, in the headless editor opening a fresh project the
## addon zip was unpacked into: the editor found and loaded the extension by
## itself, the addon's plugin enables, and the editor's help shows the class
## reference compiled into the extension. Prints "editor: N passed, M
## failed" and quits.

const PLANNED := 6
const CLASSES := ["SmgGraph", "SmgCharacter", "SmgSkeletonModifier", "SmgGraphLoader"]
## A phrase of each class's brief description in doc_classes/, as the help
## page shows it (BBCode links become plain names).
const BRIEFS := {
	"SmgCharacter": "A character that follows a path with motion from an SmgGraph",
	"SmgGraph": "A baked libsmg motion graph",
	"SmgSkeletonModifier": "Applies an SmgCharacter's pose",
	"SmgGraphLoader": "Loads .smg files as SmgGraph resources",
}
const WAIT_MS := 60000
var passed := 0
var failed := 0


func check(ok: bool, what: String) -> void:
	if ok:
		passed += 1
		print("PASS ", what)
	else:
		failed += 1
		print("FAIL ", what)


func _ready() -> void:
	var missing := CLASSES.filter(func(c): return not ClassDB.class_exists(c))
	check(missing.is_empty(), "the editor loaded the extension (missing classes: %s)" % [missing])
	EditorInterface.set_plugin_enabled("libsmg", true)
	check(EditorInterface.is_plugin_enabled("libsmg"), "the addon's plugin (plugin.cfg) enables")
	# The help is built in the background: ask again until the page shows
	# the description, for at most WAIT_MS in all.
	var deadline := Time.get_ticks_msec() + WAIT_MS
	for cls in BRIEFS:
		var text := help_text(cls)
		while not BRIEFS[cls] in text and Time.get_ticks_msec() < deadline:
			await get_tree().create_timer(0.25).timeout
			text = help_text(cls)
		check(BRIEFS[cls] in text, "the editor's help shows the class reference of %s" % cls)
		if not BRIEFS[cls] in text:
			print("  help page: ", text.substr(0, 300).c_escape())
	print("editor: %d passed, %d failed" % [passed, failed])
	get_tree().quit()


## The text of the help page for cls (the script editor names each help
## tab after its class), or "" while there is none.
func help_text(cls: String) -> String:
	var se := EditorInterface.get_script_editor()
	se.goto_help("class_name:" + cls)
	for help in se.find_children("*", "EditorHelp", true, false):
		if help.name == cls:
			for label in help.find_children("*", "RichTextLabel", true, false):
				return label.get_parsed_text()
	return ""
