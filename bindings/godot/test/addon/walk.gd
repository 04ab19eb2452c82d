extends Node3D
## make test-godot-addon: walk.tscn run from a fresh project with the addon
## zip unpacked into it. The SmgCharacter (graph = res://default.smg, set in
## the scene) follows the Path3D's curve for 8 s at 30 fps; it must have
## gone along the curve and stayed on it, with its skeleton animated. Also
## checks the installed addon's files against smg.gdextension. Prints
## "addon: N passed, M failed" and quits.

const PLANNED := 7
const FRAMES := 240
var passed := 0
var failed := 0
var frame := 0
var start_pose := []
@onready var walker: SmgCharacter = $Walker
@onready var curve: Curve3D = $Path.curve


func check(ok: bool, what: String) -> void:
	if ok:
		passed += 1
		print("PASS ", what)
	else:
		failed += 1
		print("FAIL ", what)


func _ready() -> void:
	check_install()
	check(walker.graph != null and walker.graph.is_loaded(), "the scene's SmgGraph (res://default.smg) loaded")
	var skel := walker.create_skeleton()
	for b in skel.get_bone_count():
		start_pose.append(skel.get_bone_pose_rotation(b))
	check(walker.set_path_curve(curve) == OK, "set_path_curve(Path3D.curve)")


## The installed files are the ones smg.gdextension names.
func check_install() -> void:
	var cfg := ConfigFile.new()
	check(cfg.load("res://addons/libsmg/smg.gdextension") == OK, "addons/libsmg/smg.gdextension parses")
	var libs := []
	for key in ["linux.debug.x86_64", "linux.release.x86_64", "windows.debug.x86_64", "windows.release.x86_64"]:
		var lib: String = cfg.get_value("libraries", key, "")
		if lib != "" and FileAccess.file_exists(lib):
			libs.append(key)
	check(libs.size() == 4, "libraries for linux and windows, debug and release, all present (%s)" % [libs])
	# each icon a class of ours, and an SVG Godot's renderer draws
	var icons := []
	for cls in cfg.get_section_keys("icons"):
		var icon := Image.new()
		var svg := FileAccess.get_file_as_bytes(cfg.get_value("icons", cls))
		if ClassDB.class_exists(cls) and icon.load_svg_from_buffer(svg) == OK and icon.get_width() == 16:
			icons.append(cls)
	check(icons.size() == 3, "a 16x16 SVG icon for each class shown in the editor (%s)" % [icons])


func _process(_delta: float) -> void:
	frame += 1
	if frame < FRAMES:
		return
	set_process(false)
	var pos := walker.position
	var along := curve.get_closest_offset(pos)
	var off := pos.distance_to(curve.get_closest_point(pos))
	print("after %d frames: %.2f m along the %.2f m curve, %.3f m off it, path distance %.2f m" % [
		frame, along, curve.get_baked_length(), off, walker.get_path_distance()])
	check(along > 5.0 and off < 0.5, "the character walked along the curve (> 5 m, < 0.5 m off)")
	var skel := walker.get_child(0) as Skeleton3D
	var moved := 0
	for b in skel.get_bone_count():
		if not skel.get_bone_pose_rotation(b).is_equal_approx(start_pose[b]):
			moved += 1
	# walking turns at least both hips and knees away from the rest pose
	check(moved >= 4, "the skeleton is animated (%d of %d bones turned)" % [moved, skel.get_bone_count()])
	print("addon: %d passed, %d failed" % [passed, failed])
	get_tree().quit()
