# Headless test: SmgCharacter in a game scene (run by `make test-godot`
# through run_test.sh). Events as signals; the engine's mover in charge
# (a CharacterBody3D walked into a wall and let go); the ground measured by
# physics ray casts (a 10-degree ramp and 15 cm steps). Geometry decides:
# bone positions read back from the Skeleton3D, never the library's flags.
# The last line is "scene: N passed, M failed".
extends SceneTree

const PLANNED := 20
const DT := 1.0 / 30.0

var passed := 0
var failed := 0
var graph: SmgGraph


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
	print("scene: %d passed, %d failed" % [passed, failed])
	quit(0 if failed == 0 else 1)


func run() -> void:
	graph = load("res://default.smg")
	if not (graph is SmgGraph and graph.is_loaded()):
		check(false, "default.smg loads")
		return
	await physics_frame
	await test_events()
	await test_engine_mover()
	await test_ground()
	await test_mask()
	await test_bone_map()


func joint(side: String, part: String) -> int:
	for j in graph.get_joint_count():
		var n := graph.get_joint_name(j)
		if n.begins_with(side) and n.ends_with(part):
			return j
	return -1


func new_character(parent: Node) -> SmgCharacter:
	var c := SmgCharacter.new()
	c.graph = graph
	c.active = false  # stepped by hand at exactly 1/30 s
	parent.add_child(c)
	c.create_skeleton()
	return c


func skeleton_of(c: SmgCharacter) -> Skeleton3D:
	for n in c.get_children():
		if n is Skeleton3D:
			return n
	return null


func bone_world(skel: Skeleton3D, j: int) -> Vector3:
	return skel.global_transform * skel.get_bone_global_pose(j).origin


# ---------------- events ----------------

func test_events() -> void:
	var c := new_character(root)
	var skel := skeleton_of(c)
	var toes := [joint("Left", "ToeBase"), joint("Right", "ToeBase")]
	c.set_path(PackedVector3Array([Vector3(0, 0, 0), Vector3(0, 0, 6), Vector3(3, 0, 10)]))
	var run_id := c.add_transition(2.0, graph.find_style("run"))
	var wave_id := c.add_splice(1.0, graph.find_action("wave"))
	var reached := []
	var steps := []
	var ends := [0]
	var step_err := [0.0]
	c.constraint_reached.connect(func(id, value, is_splice): reached.append([id, value, is_splice]))
	c.footstep.connect(func(foot, pos, strength):
		steps.append([foot, strength])
		# where the toe is in this frame (signals come after the pose)
		step_err[0] = max(step_err[0], pos.distance_to(bone_world(skel, toes[foot]))))
	c.path_end_reached.connect(func(): ends[0] += 1)
	for i in 450:
		c.step(DT)
	var ids := reached.map(func(r): return r[0])
	check(ids.count(run_id) == 1 and ids.count(wave_id) == 1 and reached.size() == 2,
		"constraint_reached once per constraint with its id: %s" % [reached])
	var kinds_ok := false
	for r in reached:
		if r[0] == wave_id:
			kinds_ok = r[2] == true and r[1] == graph.find_action("wave")
	check(kinds_ok, "the splice's event carries its action and is_splice")
	var feet_ok := steps.size() >= 10 and steps.all(func(s): return (s[0] == 0 or s[0] == 1) and s[1] >= 0.0)
	check(feet_ok, "footstep: %d steps, foot 0/1, strength >= 0" % steps.size())
	check(step_err[0] < 0.02, "footstep positions are the landing toe (worst %.4f m)" % step_err[0])
	check(ends[0] == 1, "path_end_reached once (%d)" % ends[0])
	c.queue_free()
	await process_frame


# ---------------- engine mover ----------------

# A character under a CharacterBody3D in engine-mover mode walks +Z; with
# `wall` a 45-degree wall stands across the path until `free_at` steps.
# Returns per step: body-space joint positions, path error, contact.
func mover_walk(with_wall: bool, free_at: int, steps: int) -> Dictionary:
	var body := CharacterBody3D.new()
	body.motion_mode = CharacterBody3D.MOTION_MODE_FLOATING
	body.collision_layer = 2
	body.collision_mask = 1
	var shape := CollisionShape3D.new()
	var capsule := CapsuleShape3D.new()
	capsule.radius = 0.25
	capsule.height = 1.6
	shape.shape = capsule
	shape.position = Vector3(0, 0.8, 0)
	body.add_child(shape)
	root.add_child(body)
	var wall: StaticBody3D = null
	if with_wall:
		wall = StaticBody3D.new()
		var ws := CollisionShape3D.new()
		var box := BoxShape3D.new()
		box.size = Vector3(8, 2, 0.2)
		ws.shape = box
		wall.add_child(ws)
		wall.position = Vector3(0, 1, 4)
		wall.rotation.y = deg_to_rad(45)
		root.add_child(wall)
	var c := SmgCharacter.new()
	c.graph = graph
	c.active = false
	c.root_motion_mode = 1
	body.add_child(c)
	c.create_skeleton()
	var skel := skeleton_of(c)
	c.set_path(PackedVector3Array([Vector3(0, 0, 0), Vector3(0, 0, 16)]))
	await physics_frame
	await physics_frame
	var poses := []
	var errors := []
	var contact := -1
	for i in steps:
		if wall != null and i == free_at:
			root.remove_child(wall)
			wall.free()
			wall = null
		c.step(DT)
		# the engine's mover: the step's root motion through move_and_slide
		body.velocity = c.get_root_motion() / body.get_physics_process_delta_time()
		body.velocity.y = 0.0
		body.move_and_slide()
		body.rotation.y += c.get_root_motion_yaw()
		if body.get_slide_collision_count() > 0 and contact < 0:
			contact = i
		c.set_ground_position(body.global_position, body.rotation.y)
		var p := PackedVector3Array()
		for j in graph.get_joint_count():
			p.append(skel.get_bone_global_pose(j).origin)  # body space
		poses.append(p)
		errors.append(c.get_path_error())
	body.queue_free()
	if wall != null:
		wall.queue_free()
	await process_frame
	return {"poses": poses, "errors": errors, "contact": contact}


func largest_step(poses: Array, from: int, to: int) -> float:
	var worst := 0.0
	for i in range(max(from, 1), min(to, poses.size())):
		for j in poses[i].size():
			worst = max(worst, poses[i][j].distance_to(poses[i - 1][j]))
	return worst


func test_engine_mover() -> void:
	var steps := 330
	var free_at := 180  # the wall goes after 6 s
	var free_run: Dictionary = await mover_walk(false, -1, steps)
	var t: Dictionary = await mover_walk(true, free_at, steps)
	var pushed := 0.0
	for i in free_at:
		pushed = max(pushed, t.errors[i])
	check(t.contact > 0 and pushed > 0.3,
		"the wall stopped the body (contact at step %d, pushed %.2f m off the path)" % [t.contact, pushed])
	var own := largest_step(free_run.poses, 60, steps)
	var blocked := largest_step(t.poses, t.contact, free_at + 8)  # from the contact until 0.25 s after
	check(blocked <= own * 1.05,
		"no pose jump at the wall: largest joint step from the contact %.3f m, free motion %.3f m" % [blocked, own])
	var normal := 0.0
	for i in range(60, steps):
		normal = max(normal, free_run.errors[i])
	var back := -1
	for i in range(free_at, steps):
		if t.errors[i] <= normal + 0.02:
			back = i
			break
	check(back >= 0 and back - free_at <= 30,
		"back on the path %.2f s after the wall went (error <= %.3f m)" % [(back - free_at) * DT, normal + 0.02])


# ---------------- uneven ground ----------------

func add_box(size: Vector3, xform: Transform3D) -> StaticBody3D:
	var b := StaticBody3D.new()
	var s := CollisionShape3D.new()
	var box := BoxShape3D.new()
	box.size = size
	s.shape = box
	b.add_child(s)
	b.transform = xform
	root.add_child(b)
	return b


const RAMP_Z := 2.0
const RAMP_LEN := 6.0
const RAMP_DEG := 10.0
const STEP_H := 0.15
const STEP_D := 0.5
const STEP_N := 6


func ramp_height(z: float) -> float:
	return tan(deg_to_rad(RAMP_DEG)) * clamp(z - RAMP_Z, 0.0, RAMP_LEN)


func steps_height(z: float) -> float:
	if z < RAMP_Z:
		return 0.0
	return STEP_H * min(floor((z - RAMP_Z) / STEP_D) + 1.0, STEP_N)


# The ground as physics bodies: a floor, then a ramp or stairs, a plateau.
func build_ground(kind: String) -> Array:
	var bodies := []
	bodies.append(add_box(Vector3(6, 0.2, 10), Transform3D(Basis(), Vector3(0, -0.1, RAMP_Z - 5))))
	if kind == "ramp":
		var a := deg_to_rad(RAMP_DEG)
		var l := RAMP_LEN / cos(a)
		var top_mid := Vector3(0, ramp_height(RAMP_Z + RAMP_LEN / 2), RAMP_Z + RAMP_LEN / 2)
		var basis := Basis(Vector3.RIGHT, -a)
		bodies.append(add_box(Vector3(6, 0.2, l), Transform3D(basis, top_mid - basis.y * 0.1)))
		var top := ramp_height(RAMP_Z + RAMP_LEN)
		bodies.append(add_box(Vector3(6, 0.2, 10), Transform3D(Basis(), Vector3(0, top - 0.1, RAMP_Z + RAMP_LEN + 5))))
	else:
		for i in STEP_N:
			var top := STEP_H * (i + 1)
			var z0 := RAMP_Z + STEP_D * i
			bodies.append(add_box(Vector3(6, top + 0.2, 20 - STEP_D * i),
				Transform3D(Basis(), Vector3(0, top / 2 - 0.1, z0 + (20 - STEP_D * i) / 2))))
	return bodies


# Walks 11 m up +Z; returns the planted toes' heights above `surface`
# (planted: toe slower than 0.15 m/s, after the first second).
func toe_heights(kind: String) -> PackedFloat32Array:
	var bodies := build_ground(kind) if kind != "flat" else []
	for i in 2:
		await physics_frame
	var c := new_character(root)
	c.ground_probing = kind != "flat"
	var skel := skeleton_of(c)
	var toes := [joint("Left", "ToeBase"), joint("Right", "ToeBase")]
	c.set_path(PackedVector3Array([Vector3(0, 0, 0), Vector3(0, 0, 11)]))
	var prev := [Vector3.ZERO, Vector3.ZERO]
	var out := PackedFloat32Array()
	for i in 300:
		c.step(DT)
		for f in 2:
			var p := bone_world(skel, toes[f])
			var surface := 0.0
			if kind == "ramp":
				surface = ramp_height(p.z)
			elif kind == "steps":
				surface = steps_height(p.z)
			if i >= 30 and p.distance_to(prev[f]) / DT < 0.15:
				out.append(p.y - surface)
			prev[f] = p
	print("%s: root height at the end %.3f m" % [kind, c.get_root_position().y])
	c.queue_free()
	for b in bodies:
		b.queue_free()
	await process_frame
	return out


func median(a: PackedFloat32Array) -> float:
	var s := Array(a)
	s.sort()
	return s[s.size() / 2] if s.size() > 0 else 0.0


func test_ground() -> void:
	var flat: PackedFloat32Array = await toe_heights("flat")
	var h0 := median(flat)
	check(flat.size() > 50, "planted toe frames on flat ground: %d (height %.3f m)" % [flat.size(), h0])
	for kind in ["ramp", "steps"]:
		var hs: PackedFloat32Array = await toe_heights(kind)
		var worst := 0.0
		for h in hs:
			worst = max(worst, abs(h - h0))
		check(hs.size() > 50, "%s: planted toe frames %d" % [kind, hs.size()])
		check(worst <= 0.02, "%s: planted toes within 2 cm of the surface (worst %.4f m)" % [kind, worst])
	var c := new_character(root)
	c.ground_probing = true
	c.set_path(PackedVector3Array([Vector3(0, 0, 0), Vector3(0, 0, 3)]))
	c.ground_collision_mask = 0  # sees nothing: stays on its own height
	for i in 30:
		c.step(DT)
	check(abs(c.get_root_position().y) < 1e-4, "with no ground in the mask the height stays (%.5f)" % c.get_root_position().y)
	c.queue_free()
	await process_frame


# ---------------- blending with an AnimationTree ----------------

# An AnimationTree holds an "aim" pose on one upper-body and one lower-body
# bone; the modifier after it takes libsmg's lower body only. A second
# character on the same path, without modifier, gives libsmg's own pose.
func test_mask() -> void:
	var c := new_character(root)
	var ref := new_character(root)
	var skel := skeleton_of(c)
	var ref_skel := skeleton_of(ref)
	var arm := joint("Left", "Arm")
	var leg := joint("Left", "UpLeg")
	var hip := joint("Right", "UpLeg")
	var aim := Quaternion(Vector3(1, 0, 0), 0.9)
	var anim := Animation.new()
	anim.length = 1.0
	anim.loop_mode = Animation.LOOP_LINEAR
	for j in [arm, leg]:
		var tr := anim.add_track(Animation.TYPE_ROTATION_3D)
		anim.track_set_path(tr, NodePath("%s:%s" % [skel.name, graph.get_joint_name(j)]))
		anim.rotation_track_insert_key(tr, 0.0, aim)
	var lib := AnimationLibrary.new()
	lib.add_animation("aim", anim)
	var tree := AnimationTree.new()
	tree.add_animation_library("", lib)
	var node := AnimationNodeAnimation.new()
	node.animation = "aim"
	tree.tree_root = node
	c.add_child(tree)
	tree.root_node = NodePath("..")
	tree.active = true
	var mod := SmgSkeletonModifier.new()
	mod.upper_body_weight = 0.0  # upper body from the AnimationTree
	mod.set_bone_weight(graph.get_joint_name(hip), 0.5)
	skel.add_child(mod)
	var seen := {"n": 0, "arm": 0.0, "leg": 0.0, "hip": 0.0}
	mod.modification_processed.connect(func():
		seen.n += 1
		if seen.n > 1:  # the AnimationTree first blends in the frame after it starts
			seen.arm = max(seen.arm, skel.get_bone_pose_rotation(arm).angle_to(aim))
		seen.leg = max(seen.leg, skel.get_bone_pose_rotation(leg).angle_to(ref_skel.get_bone_pose_rotation(leg)))
		var half := skel.get_bone_pose_rotation(hip)
		var want := skel.get_bone_rest(hip).basis.get_rotation_quaternion().slerp(ref_skel.get_bone_pose_rotation(hip), 0.5)
		seen.hip = max(seen.hip, half.angle_to(want)))
	for p in [c, ref]:
		p.set_path(PackedVector3Array([Vector3(0, 0, 0), Vector3(0, 0, 8)]))
	for i in 40:
		c.step(DT)
		ref.step(DT)
		await process_frame
	check(seen.n >= 30 and seen.arm < 5e-3,
		"upper body keeps the AnimationTree's pose under the modifier (%d frames, worst %.5f rad)" % [seen.n, seen.arm])
	check(seen.leg < 5e-3, "lower body is libsmg's pose (worst %.5f rad from the unmasked character)" % seen.leg)
	check(seen.hip < 0.02, "a bone weight of 0.5 blends halfway (worst %.4f rad)" % seen.hip)
	c.queue_free()
	ref.queue_free()
	await process_frame


# ---------------- humanoid rigs through a BoneMap ----------------

# The graph's joints as Godot's SkeletonProfileHumanoid names them; what a
# user's BoneMap would say for this skeleton (written here by hand, from
# the default graph's CMU-style names).
const PROFILE_OF := {
	"Hips": "Hips", "LowerBack": "Spine", "Spine": "Chest", "Spine1": "UpperChest", "Neck": "Neck",
	"Head": "Head", "LeftShoulder": "LeftShoulder", "LeftArm": "LeftUpperArm",
	"LeftForeArm": "LeftLowerArm", "LeftHand": "LeftHand", "RightShoulder": "RightShoulder",
	"RightArm": "RightUpperArm", "RightForeArm": "RightLowerArm", "RightHand": "RightHand",
	"LeftUpLeg": "LeftUpperLeg", "LeftLeg": "LeftLowerLeg", "LeftFoot": "LeftFoot", "LeftToeBase": "LeftToes",
	"RightUpLeg": "RightUpperLeg", "RightLeg": "RightLowerLeg", "RightFoot": "RightFoot",
	"RightToeBase": "RightToes",
}


# A rig whose bone names follow no convention ("bone_07"), driven through a
# BoneMap only, against a character on the graph's own bone names.
func test_bone_map() -> void:
	var c := SmgCharacter.new()
	c.graph = graph
	c.active = false
	root.add_child(c)
	var skel: Skeleton3D = graph.build_skeleton()
	var bm := BoneMap.new()
	bm.profile = SkeletonProfileHumanoid.new()
	var mapped := []
	var unmapped := []
	for j in graph.get_joint_count():
		var own := "bone_%02d" % j
		skel.set_bone_name(j, own)
		var jn := graph.get_joint_name(j)
		if PROFILE_OF.has(jn):
			bm.set_skeleton_bone_name(PROFILE_OF[jn], own)
			mapped.append(j)
		else:
			unmapped.append(j)
	c.add_child(skel)
	c.bone_map = bm
	var ref := new_character(root)
	var ref_skel := skeleton_of(ref)
	for p in [c, ref]:
		p.set_path(PackedVector3Array([Vector3(0, 0, 0), Vector3(0, 0, 3), Vector3(2, 0, 6)]))
	var worst := 0.0
	var root_err := 0.0
	var moved := 0
	var untouched := true
	for i in 60:
		c.step(DT)
		ref.step(DT)
		for j in mapped:
			var q := skel.get_bone_pose_rotation(j)
			worst = max(worst, q.angle_to(ref_skel.get_bone_pose_rotation(j)))
			if i == 59 and not q.is_equal_approx(Quaternion.IDENTITY):
				moved += 1
		root_err = max(root_err, skel.get_bone_pose_position(0).distance_to(ref_skel.get_bone_pose_position(0)))
		for j in unmapped:
			untouched = untouched and skel.get_bone_pose_rotation(j).is_equal_approx(Quaternion.IDENTITY)
	check(moved >= mapped.size() / 2 and worst < 5e-3 and root_err < 1e-4,
		"BoneMap only: %d of the mapped bones turned, all posed as by name (worst %.5f rad, root %.5f m)" % [moved, worst, root_err])
	check(untouched, "bones the BoneMap does not name are left alone (%d)" % unmapped.size())
	# the same rig without the BoneMap: nothing matches
	c.bone_map = null
	skel.reset_bone_poses()
	c.step(DT)
	var still := true
	for j in graph.get_joint_count():
		still = still and skel.get_bone_pose_rotation(j).is_equal_approx(Quaternion.IDENTITY)
	check(still, "without the BoneMap the unconventional names match nothing")
	c.queue_free()
	ref.queue_free()
	await process_frame
