# Headless test: SmgCharacter driving a rig that is not the capture skeleton
# (run by `make test-godot` through run_test.sh when a retargeted graph is
# given). rig.smg is the synthetic clips baked onto the generated test rig
# (smg-bake --target); rig_ref.csv holds, per frame time, the world joint
# positions smg-synth produced on the same graph and path. Here the rig is a
# Skeleton3D with the graph's joints and rest geometry but bone axes of its
# own (as a glTF import has): the character must pose it so that every bone
# lands where smg-synth put the joint. The last line is
# "rig: N passed, M failed".
extends SceneTree

const PLANNED := 6
const PATH := [Vector3(0, 0, 0), Vector3(0, 0, 4), Vector3(2, 0, 7), Vector3(2, 0, 12)]
const FRAMES := 170
const TOLERANCE := 0.01  # metres

var passed := 0
var failed := 0


func check(ok: bool, what: String) -> void:
	if ok:
		passed += 1
		print("PASS ", what)
	else:
		failed += 1
		print("FAIL ", what)


func _initialize() -> void:
	await run()
	if passed + failed != PLANNED:
		failed += 1
		print("FAIL ran %d checks, planned %d" % [passed + failed - 1, PLANNED])
	print("rig: %d passed, %d failed" % [passed, failed])
	quit(0 if failed == 0 else 1)


# Frame index (time * 30) -> world joint positions, from smg-synth.
func load_reference() -> Dictionary:
	var ref := {}
	var f := FileAccess.open("res://rig_ref.csv", FileAccess.READ)
	if f == null:
		return ref
	while not f.eof_reached():
		var parts := f.get_line().split(",")
		if parts.size() < 4:
			continue
		var p := PackedFloat64Array()
		for i in range(1, parts.size()):
			p.append(parts[i].to_float())
		ref[int(round(parts[0].to_float() * 30.0))] = p
	return ref


# The graph's skeleton with a rest rotation per bone that is not the
# graph's world-aligned rest; same joint positions at rest.
func skeleton_with_own_axes(g: SmgGraph) -> Skeleton3D:
	var skel := Skeleton3D.new()
	var global_rest: Array = []
	for j in g.get_joint_count():
		skel.add_bone(g.get_joint_name(j).replace(":", "_"))  # as Godot's importers name bones
		var p := g.get_joint_parent(j)
		if p >= 0:
			skel.set_bone_parent(j, p)
		var q := Quaternion(Vector3(sin(1.3 * j), cos(0.7 * j), 0.5).normalized(), 0.4 + 0.3 * j)
		global_rest.append(q)
		var parent_q: Quaternion = global_rest[p] if p >= 0 else Quaternion.IDENTITY
		var origin: Vector3 = parent_q.inverse() * g.get_joint_rest_offset(j) if p >= 0 else Vector3.ZERO
		skel.set_bone_rest(j, Transform3D(Basis(parent_q.inverse() * q), origin))
	skel.reset_bone_poses()
	return skel


func run() -> void:
	var g = load("res://rig.smg")
	check(g is SmgGraph and g.is_loaded() and g.get_joint_name(0) == "mixamorig:Hips",
		"the retargeted graph loads with the rig's joints")
	var ref := load_reference()
	check(ref.size() > 100, "smg-synth reference read (%d frames)" % ref.size())
	var skel := skeleton_with_own_axes(g)
	var c := SmgCharacter.new()
	c.graph = g
	c.active = false  # stepped by hand at smg-synth's 1/30 s
	root.add_child(c)
	c.add_child(skel)
	c.set_path(PackedVector3Array(PATH))
	await process_frame
	var compared := 0
	var worst := 0.0
	for i in FRAMES:
		c.step(1.0 / 30.0)
		var key := int(round(c.get_time() * 30.0))
		if key < 1 or not ref.has(key):
			continue
		var p: PackedFloat64Array = ref[key]
		for j in g.get_joint_count():
			var world := skel.global_transform * skel.get_bone_global_pose(j).origin
			worst = max(worst, world.distance_to(Vector3(p[3 * j], p[3 * j + 1], p[3 * j + 2])))
		compared += 1
	var rest_rot := skel.get_bone_global_rest(3).basis.get_rotation_quaternion()
	await renamed_to_profile(g, ref)
	check(not rest_rot.is_equal_approx(Quaternion.IDENTITY), "the rig's bones have their own axes")
	check(compared > 100, "frames compared with smg-synth: %d" % compared)
	check(worst < TOLERANCE, "every bone within %.2f m of smg-synth's joint (worst %.4f m)" % [TOLERANCE, worst])
	c.queue_free()
	await process_frame


# Godot's importer with a BoneMap renames a rig's bones to the
# SkeletonProfileHumanoid names; the graph keeps Mixamo's. The character must
# find every joint by its profile name (this table is the test's own).
const MIXAMO_PROFILE := {
	"Hips": "Hips", "Spine": "Spine", "Spine1": "Chest", "Spine2": "UpperChest", "Neck": "Neck", "Head": "Head",
	"LeftShoulder": "LeftShoulder", "LeftArm": "LeftUpperArm", "LeftForeArm": "LeftLowerArm", "LeftHand": "LeftHand",
	"RightShoulder": "RightShoulder", "RightArm": "RightUpperArm", "RightForeArm": "RightLowerArm",
	"RightHand": "RightHand", "LeftUpLeg": "LeftUpperLeg", "LeftLeg": "LeftLowerLeg", "LeftFoot": "LeftFoot",
	"LeftToeBase": "LeftToes", "RightUpLeg": "RightUpperLeg", "RightLeg": "RightLowerLeg",
	"RightFoot": "RightFoot", "RightToeBase": "RightToes",
}


func renamed_to_profile(g: SmgGraph, ref: Dictionary) -> void:
	var skel := skeleton_with_own_axes(g)
	for j in g.get_joint_count():
		skel.set_bone_name(j, MIXAMO_PROFILE.get(g.get_joint_name(j).trim_prefix("mixamorig:"), "x%d" % j))
	var c := SmgCharacter.new()
	c.graph = g
	c.active = false
	root.add_child(c)
	c.add_child(skel)
	c.set_path(PackedVector3Array(PATH))
	var worst := 0.0
	for i in FRAMES:
		c.step(1.0 / 30.0)
		var key := int(round(c.get_time() * 30.0))
		if key < 1 or not ref.has(key):
			continue
		var p: PackedFloat64Array = ref[key]
		for j in g.get_joint_count():
			var world := skel.global_transform * skel.get_bone_global_pose(j).origin
			worst = max(worst, world.distance_to(Vector3(p[3 * j], p[3 * j + 1], p[3 * j + 2])))
	check(worst < TOLERANCE, "bones renamed to the humanoid profile: every bone within %.2f m (worst %.4f m)" % [TOLERANCE, worst])
	c.queue_free()
	await process_frame
