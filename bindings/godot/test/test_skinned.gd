# Headless test of the skinned character (run by run_test.sh from
# `make test-godot`): the generated body (body.gltf, written by
# smg-body-gltf from the same graph) is loaded with GLTFDocument, its
# Skeleton3D driven by SmgCharacter + SmgSkeletonModifier along the path in
# skinned_path.txt, stepped at 1/30 s. Checks: the bones carry the graph's
# joint names; every bone's world position matches forward kinematics of the
# smg-synth BVH for the same graph, path and rate (skinned.bvh); the mesh
# skinned on the CPU from Godot's bone poses and the skin's bind poses stands
# on the floor and moves with the character. Last line:
# "skinned: N passed, M failed".
extends SceneTree

const PLANNED := 6
const FPS := 30.0
const SECONDS := 8.0
const SKIN_EVERY := 10  # frames between CPU-skinned checks of the mesh

var passed := 0
var failed := 0
var graph: SmgGraph
var character: SmgCharacter
var skel: Skeleton3D
var mesh_instance: MeshInstance3D
var recorded := {}  # frame -> {name: world position}
var lowest := {}  # frame -> lowest skinned vertex y
var skinned_centre := {}  # frame -> mean skinned vertex - root, on the ground


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
	print("skinned: %d passed, %d failed" % [passed, failed])
	quit(0 if failed == 0 else 1)


func read_path() -> PackedVector3Array:
	var pts := PackedVector3Array()
	for line in FileAccess.get_file_as_string("res://skinned_path.txt").split("\n"):
		var t := line.strip_edges()
		if t.is_empty() or t.begins_with("#"):
			continue
		var xz := t.split_floats(" ", false)
		pts.append(Vector3(xz[0], 0, xz[1]))
	return pts


# Joint world positions per frame from smg-synth's BVH (rotations ZYX in
# degrees, R = Rz Ry Rx; the root also has a position).
func synth_positions(file: String) -> Array:
	var names: Array = []
	var parents: Array = []
	var offsets: Array = []
	var stack: Array = []
	var frames: Array = []
	var in_motion := false
	for raw in FileAccess.get_file_as_string(file).split("\n"):
		var line := raw.strip_edges()
		var w := line.split(" ", false)
		if w.is_empty():
			continue
		if not in_motion:
			if w[0] == "ROOT" or w[0] == "JOINT":
				names.append(w[1])
				parents.append(stack.back() if not stack.is_empty() else -1)
				offsets.append(Vector3.ZERO)
				stack.append(names.size() - 1)
			elif w[0] == "End":
				stack.append(-2)
			elif w[0] == "OFFSET" and not stack.is_empty() and stack.back() >= 0:
				offsets[stack.back()] = Vector3(float(w[1]), float(w[2]), float(w[3]))
			elif w[0] == "}":
				stack.pop_back()
			elif w[0] == "MOTION":
				in_motion = true
			continue
		if w[0] == "Frames:" or w[0] == "Frame":
			continue
		var v := line.split_floats(" ", false)
		var pos := {}
		var rot: Array = []
		var wpos: Array = []
		for j in names.size():
			var k := 3 + 3 * j
			var b := Basis(Vector3(0, 0, 1), deg_to_rad(v[k])) * Basis(Vector3(0, 1, 0), deg_to_rad(v[k + 1])) \
				* Basis(Vector3(1, 0, 0), deg_to_rad(v[k + 2]))
			if parents[j] < 0:
				rot.append(b)
				wpos.append(Vector3(v[0], v[1], v[2]))
			else:
				rot.append(rot[parents[j]] * b)
				wpos.append(wpos[parents[j]] + rot[parents[j]] * offsets[j])
			pos[names[j]] = wpos[j]
		frames.append(pos)
	return frames


func run() -> void:
	graph = load("res://default.smg")
	var doc := GLTFDocument.new()
	var state := GLTFState.new()
	var err := doc.append_from_file("res://body.gltf", state)
	var scene := doc.generate_scene(state) if err == OK else null
	var found: Array = scene.find_children("*", "Skeleton3D", true, false) if scene else []
	if not found.is_empty():
		skel = found[0]
		var meshes: Array = skel.find_children("*", "MeshInstance3D", true, false)
		mesh_instance = meshes[0] if not meshes.is_empty() else null
	check(skel != null and mesh_instance != null and mesh_instance.skin != null,
		"the generated body loads as a Skeleton3D with a skinned MeshInstance3D")
	if skel == null or mesh_instance == null or mesh_instance.skin == null:
		return
	var names_ok := skel.get_bone_count() == graph.get_joint_count()
	for j in graph.get_joint_count():
		names_ok = names_ok and skel.find_bone(graph.get_joint_name(j)) >= 0
	check(names_ok, "one bone per graph joint, same names")

	skel.get_parent().remove_child(skel)
	for n in skel.find_children("*", "", true, false):
		n.owner = null
	skel.owner = null
	scene.free()
	character = SmgCharacter.new()
	character.graph = graph
	# Stepped by hand at exactly 1/30 s like smg-synth: Godot's own process
	# delta varies around 1/30 even with --fixed-fps 30.
	character.active = false
	root.add_child(character)
	character.add_child(skel)
	var mod := SmgSkeletonModifier.new()
	skel.add_child(mod)
	mod.modification_processed.connect(_record)
	var path := read_path()
	character.set_path(path)
	await process_frame
	for i in int(SECONDS * FPS):
		character.step(1.0 / FPS)
		await process_frame

	var expected := synth_positions("res://skinned.bvh")
	var compared := 0
	var worst := 0.0
	var worst_frame := -1
	for k in recorded:
		if k >= expected.size():
			continue
		compared += 1
		for bone in recorded[k]:
			var e: float = recorded[k][bone].distance_to(expected[k][bone])
			if e > worst:
				worst = e
				worst_frame = k
	print("bones vs smg-synth: %d frames compared, worst joint %.4f m (frame %d)" % [compared, worst, worst_frame])
	check(compared >= int(SECONDS * FPS) - 10 and worst < 0.001,
		"every bone's world position matches smg-synth on the same graph and path (< 1 mm)")
	check(character.get_path_distance() > 4.0 and character.get_path_error() < 1.0,
		"the skinned character walked the path (%.1f m along, %.2f m off)" % [
			character.get_path_distance(), character.get_path_error()])
	var low_min := INF
	var low_max := -INF
	var off := 0.0
	for k in lowest:
		low_min = min(low_min, lowest[k])
		low_max = max(low_max, lowest[k])
		off = max(off, skinned_centre[k])
	print("skinned mesh: %d frames, lowest vertex %.3f .. %.3f m, centre %.3f m from the root" % [
		lowest.size(), low_min, low_max, off])
	check(lowest.size() >= 15 and abs(low_min) < 0.025 and low_max < 0.06,
		"feet at floor height: the skinned mesh's lowest point stays within 2.5 cm below / 6 cm above the floor")
	check(lowest.size() >= 15 and off < 0.3, "the skinned mesh moves with the character (centre over the root)")


# Called when the modifier has posed the skeleton (the pose is transient).
func _record() -> void:
	var k := int(round(character.get_time() * FPS))
	# Before its first step the character has no pose yet (the skeleton is
	# still at rest, the root bone at the node's origin).
	if k == 0:
		return
	var to_world := skel.global_transform
	var pos := {}
	for b in skel.get_bone_count():
		pos[skel.get_bone_name(b)] = (to_world * skel.get_bone_global_pose(b)).origin
	recorded[k] = pos
	if k % SKIN_EVERY != 0:
		return
	# Linear-blend skinning on the CPU from Godot's own data: mesh arrays,
	# the skin's bind poses, the bones' global poses.
	var skin := mesh_instance.skin
	var xf: Array = []
	for i in skin.get_bind_count():
		var bone := skin.get_bind_bone(i)
		if bone < 0:
			bone = skel.find_bone(skin.get_bind_name(i))
		xf.append(to_world * skel.get_bone_global_pose(bone) * skin.get_bind_pose(i))
	var arrays := mesh_instance.mesh.surface_get_arrays(0)
	var verts: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
	var bones: PackedInt32Array = arrays[Mesh.ARRAY_BONES]
	var weights: PackedFloat32Array = arrays[Mesh.ARRAY_WEIGHTS]
	var low := INF
	var sum := Vector3.ZERO
	for v in verts.size():
		var p := Vector3.ZERO
		for i in 4:
			var wgt := weights[v * 4 + i]
			if wgt > 0.0:
				p += wgt * (xf[bones[v * 4 + i]] * verts[v])
		low = min(low, p.y)
		sum += p
	lowest[k] = low
	var centre := sum / verts.size()
	var ground := character.get_root_position()
	skinned_centre[k] = Vector2(centre.x - ground.x, centre.z - ground.z).length()
