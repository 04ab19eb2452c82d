# Headless test of the libsmg GDExtension (run by `make test-godot`).
#
# Loads a baked graph, drives an SmgCharacter along a path with a transition
# and a splice point for a few hundred frames (--fixed-fps 30, so each frame
# is 1/30 s), and checks from GDScript that the character follows the path,
# the skeleton is animated, the signals fire, and that bad input and odd
# lifetimes give Godot errors instead of crashes. The last line is
# "godot: N passed, M failed"; check_log.sh accepts only "M = 0" with N equal
# to the number of checks planned here, plus the expected error messages.
extends SceneTree

const PLANNED := 54
const MAX_FRAMES := 600             # 20 s at 30 fps, the end comes well before
# Metres between the root's ground projection and the path while following
# it: the character is ~0.5 m wide and running turns wide.
const MAX_PATH_ERROR := 1.0
const PATH := [Vector3(0, 0, 0), Vector3(0, 0, 5), Vector3(1.5, 0, 8), Vector3(1.5, 0, 13)]
const APPENDED := [Vector3(1.5, 0, 16), Vector3(0.7, 0, 19.5)]

var passed := 0
var failed := 0
var styles_seen: Array = []
var actions_seen: Array = []
var end_count := 0
var end_frame := 0


func check(ok: bool, what: String) -> void:
	if ok:
		passed += 1
		print("PASS ", what)
	else:
		failed += 1
		print("FAIL ", what)


# Distance in the ground plane from p to the polyline.
func dist_to_path(p: Vector3, pts: Array) -> float:
	var q := Vector2(p.x, p.z)
	var best := INF
	for i in range(pts.size() - 1):
		var a := Vector2(pts[i].x, pts[i].z)
		var b := Vector2(pts[i + 1].x, pts[i + 1].z)
		var ab := b - a
		var t: float = clamp((q - a).dot(ab) / max(ab.length_squared(), 1e-9), 0.0, 1.0)
		best = min(best, q.distance_to(a + ab * t))
	return best


func path_length(pts: Array) -> float:
	var s := 0.0
	for i in range(pts.size() - 1):
		s += Vector2(pts[i].x, pts[i].z).distance_to(Vector2(pts[i + 1].x, pts[i + 1].z))
	return s


func frames(n: int) -> void:
	for i in n:
		await process_frame


func _initialize() -> void:
	await run()
	if passed + failed != PLANNED:
		failed += 1
		print("FAIL ran %d checks, planned %d" % [passed + failed - 1, PLANNED])
	print("godot: %d passed, %d failed" % [passed, failed])
	quit(0 if failed == 0 else 1)


func run() -> void:
	# --- classes ---------------------------------------------------------
	check(ClassDB.class_exists("SmgGraph") and ClassDB.class_exists("SmgCharacter")
		and ClassDB.class_exists("SmgSkeletonModifier"), "classes registered")
	check(ClassDB.is_parent_class("SmgGraph", "Resource") and ClassDB.is_parent_class("SmgCharacter", "Node3D")
		and ClassDB.is_parent_class("SmgSkeletonModifier", "SkeletonModifier3D"),
		"SmgGraph is a Resource, SmgCharacter a Node3D, SmgSkeletonModifier a SkeletonModifier3D")
	var props := ClassDB.class_get_property_list("SmgCharacter", true).map(func(p): return p.name)
	check(props.has("graph") and props.has("skeleton") and props.has("style") and props.has("action")
		and props.has("error_threshold") and props.has("ik_enabled") and props.has("steering_enabled")
		and props.has("steer_turn_rate") and props.has("steer_slide_ratio") and props.has("stop_seconds")
		and props.has("swing_clearance"),
		"inspector properties")
	check(ClassDB.class_has_signal("SmgCharacter", "style_changed") and ClassDB.class_has_signal("SmgCharacter", "action_changed")
		and ClassDB.class_has_signal("SmgCharacter", "path_end_reached"), "signals declared")

	# --- graph loading and bad files -------------------------------------
	var bad := SmgGraph.new()
	check(bad.load("res://missing.smg") == ERR_FILE_NOT_FOUND and not bad.is_loaded(), "missing graph file -> ERR_FILE_NOT_FOUND")
	var f := FileAccess.open("user://garbage.smg", FileAccess.WRITE)
	f.store_string("this is not a libsmg graph blob, just text padded out to look plausible........")
	f.close()
	check(bad.load("user://garbage.smg") != OK and not bad.is_loaded(), "garbage graph file rejected")
	var trunc := FileAccess.get_file_as_bytes("res://default.smg").slice(0, 200)
	f = FileAccess.open("user://truncated.smg", FileAccess.WRITE)
	f.store_buffer(trunc)
	f.close()
	check(bad.load("user://truncated.smg") != OK and not bad.is_loaded(), "truncated graph file rejected")
	check(bad.get_joint_count() == 0 and bad.get_style_names().is_empty() and bad.build_skeleton() == null,
		"queries on an empty SmgGraph are safe")

	var g := SmgGraph.new()
	check(g.load("res://default.smg") == OK and g.is_loaded(), "load res://default.smg")
	var abs_path := OS.get_environment("SMG_TEST_GRAPH_ABS")
	var g_abs := SmgGraph.new()
	check(abs_path != "" and g_abs.load(abs_path) == OK and g_abs.get_joint_count() == g.get_joint_count(),
		"load by absolute path")
	var nj := g.get_joint_count()
	check(nj > 1 and g.get_style_count() >= 1 and g.get_action_count() >= 1 and g.get_action_name(0) != "",
		"graph info: %d joints, styles %s, actions %s" % [nj, g.get_style_names(), g.get_action_names()])
	check(g.find_style(g.get_style_name(0)) == 0 and g.find_style("no such style") == -1, "find_style")
	var as_res = load("res://default.smg")   # through SmgGraphLoader
	check(as_res is SmgGraph and as_res.is_loaded() and as_res.get_joint_count() == nj
		and ResourceLoader.exists("res://default.smg", "SmgGraph"), ".smg files load as SmgGraph resources")

	# --- calls before a graph is set --------------------------------------
	var lonely := SmgCharacter.new()
	root.add_child(lonely)
	check(lonely.set_path(PackedVector3Array(PATH)) == ERR_UNCONFIGURED, "set_path without graph -> error")
	check(lonely.add_transition(1.0, 0) == -1 and lonely.add_splice(1.0, 0) == -1, "constraints without graph -> -1")
	check(lonely.step(0.1) != OK and lonely.get_path_length() == 0.0, "step without graph -> error, no crash")
	await frames(2)
	lonely.free()

	# --- the scene: SmgCharacter with an SmgGraph sub-resource ----------
	var scene: Node3D = load("res://character.tscn").instantiate()
	root.add_child(scene)
	var c: SmgCharacter = scene.get_node("Character")
	check(c.graph != null and c.graph.is_loaded() and is_equal_approx(c.error_threshold, 0.3), "scene properties loaded")
	var fc: SmgCharacter = scene.get_node("FileGraphCharacter")
	check(fc.graph != null and fc.graph.is_loaded() and fc.graph.resource_path == "res://default.smg",
		"scene refers to a .smg file as an ext_resource")
	c.graph = g                             # the same graph, shared with later characters
	var sk: Skeleton3D = c.create_skeleton()
	var names_ok := sk != null and sk.get_bone_count() == nj
	if names_ok:
		for j in nj:
			names_ok = names_ok and sk.get_bone_name(j) == g.get_joint_name(j)
	check(names_ok, "create_skeleton matches the graph's joints")

	c.style_changed.connect(func(s, n): styles_seen.append([s, n]))
	c.action_changed.connect(func(a, n): actions_seen.append([a, n]))
	c.path_end_reached.connect(func(): end_count += 1)

	check(c.set_path(PackedVector3Array()) == ERR_INVALID_PARAMETER, "empty path -> error")
	check(c.set_path(PackedVector3Array(PATH)) == OK, "set_path")
	check(abs(c.get_path_length() - path_length(PATH)) < 1e-3, "path length %.3f" % c.get_path_length())
	var want_style := 1 if g.get_style_count() > 1 else 0
	var want_action := 1 if g.get_action_count() > 1 else 0
	var tid: int = c.add_transition(8.5, want_style)   # run after the bend
	var sid: int = c.add_splice(2.5, want_action)
	check(tid > 0 and sid > 0 and tid != sid, "transition and splice points added")
	check(c.add_transition(1.0, 9999) == -1, "unknown style rejected")
	var tmp: int = c.add_splice(6.0, 0)
	check(c.move_constraint(tmp, 7.0) == OK and c.remove_constraint(tmp) == OK, "move and remove a constraint")
	check(c.remove_constraint(tmp) == ERR_DOES_NOT_EXIST, "removing twice -> error")

	var legs := [sk.find_bone(g.get_joint_name(nj / 4)), sk.find_bone(g.get_joint_name(nj - 3))]
	await frames(1)
	var start_rot := []
	for j in nj:
		start_rot.append(sk.get_bone_pose_rotation(j))
	# Walk the path; 3 s in, extend it like a user still drawing. Tracking
	# is judged until the end is reached (what a character does after the
	# end, e.g. run on along committed motion, is not path following).
	var full: Array = PATH + APPENDED
	var max_err := 0.0
	var samples: Array = []
	var start_pos := c.position
	var appended := ERR_BUG
	var steps := 0
	var end_pos = null
	while steps < MAX_FRAMES and (end_pos == null or steps < end_frame + 15):
		await process_frame
		steps += 1
		if steps == 90:
			appended = c.append_path_points(PackedVector3Array(APPENDED))
		if end_pos == null:
			max_err = max(max_err, dist_to_path(c.position, full if steps >= 90 else PATH))
			if c.is_path_end_reached():
				end_pos = c.position
				end_frame = steps
		if steps % 15 == 0:
			samples.append(sk.get_bone_pose_rotation(legs[0]))
			print("  frame %d: ground %s, %.2f m along, %.2f m off, style %d, action %d" % [steps, c.position,
				c.get_path_distance(), dist_to_path(c.position, full if steps >= 90 else PATH), c.style, c.action])
	var travelled := c.get_path_distance()
	print("travelled %.2f m of %.2f, max ground error %.3f m, end at frame %d at %s, time %.2f s, final %s" % [
		travelled, c.get_path_length(), max_err, end_frame, end_pos, c.get_time(), c.position])
	check(abs(c.get_time() - (steps + 1) / 30.0) < 0.1, "stepped %.2f s in %d frames of 1/30 s" % [c.get_time(), steps + 1])
	check(c.position.distance_to(start_pos) > 3.0, "root moved %.2f m" % c.position.distance_to(start_pos))
	check(max_err < MAX_PATH_ERROR, "root stayed within %.2f m of the path (max %.3f)" % [MAX_PATH_ERROR, max_err])
	check(appended == OK and c.get_path_length() > path_length(full) - 0.01, "append_path_points extends the path")
	check(travelled > path_length(PATH) + 1.0, "character continued on the appended points (%.2f m)" % travelled)
	check(end_pos != null and dist_to_path(end_pos, [full[-1], full[-1]]) < 1.0, "reached the end of the path")
	var changed := 0
	for j in nj:
		if sk.get_bone_pose_rotation(j).angle_to(start_rot[j]) > 0.05:
			changed += 1
	check(changed >= 4, "bone poses changed (%d of %d bones)" % [changed, nj])
	var varied := 0
	for i in range(1, samples.size()):
		if samples[i].angle_to(samples[i - 1]) > 0.02:
			varied += 1
	check(varied >= samples.size() / 2, "limb keeps moving over time (%d/%d samples)" % [varied, samples.size() - 1])
	var root_bone_pos := sk.get_bone_pose_position(0)
	check(root_bone_pos.y > 0.3 and Vector2(root_bone_pos.x, root_bone_pos.z).length() < 0.5,
		"root bone above ground under the node (%s)" % root_bone_pos)
	check(want_style == 0 or styles_seen.any(func(e): return e[0] == want_style and e[1] == g.get_style_name(want_style)),
		"style_changed fired: %s" % [styles_seen])
	check(want_action == 0 or actions_seen.any(func(e): return e[0] == want_action and e[1] == g.get_action_name(want_action)),
		"action_changed fired: %s" % [actions_seen])
	check(end_count == 1, "path_end_reached fired once (%d)" % end_count)
	# the properties report what the character plays: the last style it
	# switched to (a run walks its last metres to stop on both feet, so at
	# the end that is not always the one asked for)
	var last_style: int = styles_seen[-1][0] if styles_seen.size() > 0 else 0
	check(c.style == last_style and c.action == want_action,
		"style/action properties follow the character (style %d, last switch %s)" % [c.style, styles_seen])

	# --- a new path from a Curve3D ----------------------------------------
	check(c.set_path_curve(Curve3D.new()) != OK, "empty Curve3D -> error")
	var curve := Curve3D.new()
	curve.add_point(c.position)
	curve.add_point(c.position + Vector3(0, 0, 3))
	check(c.set_path_curve(curve) == OK and c.get_path_length() > 2.5, "set_path_curve")
	check(not c.is_path_end_reached(), "a new path clears the end state")

	# --- SmgSkeletonModifier: the pose applied in the modifier stage ------
	var cm := SmgCharacter.new()
	cm.position = Vector3(10, 0, 0)         # start where its path starts
	cm.graph = g
	root.add_child(cm)
	var skm: Skeleton3D = cm.create_skeleton()
	var mod := SmgSkeletonModifier.new()
	skm.add_child(mod)
	var probe := skm.find_bone(g.get_joint_name(nj / 4))
	var mod_rots: Array = []
	mod.modification_processed.connect(func(): mod_rots.append(skm.get_bone_pose_rotation(probe)))
	cm.set_path(PackedVector3Array([Vector3(10, 0, 0), Vector3(10, 0, 6)]))
	await frames(50)
	var mod_varied := 0
	for i in range(1, mod_rots.size()):
		if mod_rots[i].angle_to(mod_rots[i - 1]) > 0.005:
			mod_varied += 1
	check(mod_rots.size() >= 40 and mod_varied >= mod_rots.size() / 2,
		"SmgSkeletonModifier poses the skeleton in the modifier stage (%d updates, %d varied)" % [mod_rots.size(), mod_varied])
	mod.active = false                      # the character takes over again
	await frames(5)
	var own_rots: Array = []
	for i in 10:
		await process_frame
		own_rots.append(skm.get_bone_pose_rotation(probe))
	var own_varied := 0
	for i in range(1, own_rots.size()):
		if own_rots[i].angle_to(own_rots[i - 1]) > 0.005:
			own_varied += 1
	check(own_varied >= 5, "inactive modifier: the character writes bone poses itself (%d/9 varied)" % own_varied)
	skm.free()                              # modifier goes with it
	await frames(3)
	check(cm.step(0.1) == OK, "modifier freed, character still steps")
	cm.free()

	# --- robustness --------------------------------------------------------
	# Reload the graph under a running character: it is rebuilt on the new one.
	var pos_before := c.position
	check(g.load("res://default.smg") == OK, "reload the graph while in use")
	await frames(10)
	check(c.position.distance_to(pos_before) < 1.5 and c.get_time() < 1.0, "character rebuilt on the reloaded graph")
	# Wrong object for the graph property.
	var not_graph := Node3D.new()
	c.call("set_graph", not_graph)
	not_graph.free()
	check(c.graph == g, "non-SmgGraph rejected")
	# Free the skeleton first, then keep stepping.
	sk.free()
	await frames(5)
	check(c.step(0.1) == OK, "stepping after the skeleton was freed")
	# A skeleton with bones the graph lacks and lacking most of the graph's.
	var sk2 := Skeleton3D.new()
	sk2.add_bone(g.get_joint_name(0))
	sk2.add_bone("NotInTheGraph")
	sk2.add_bone(g.get_joint_name(nj - 1))
	sk2.set_bone_parent(1, 0)
	var extra_before := sk2.get_bone_pose_rotation(1)
	c.add_child(sk2)
	c.set_path(PackedVector3Array([c.position, c.position + Vector3(0, 0, 4)]))
	await frames(20)
	check(sk2.get_bone_pose_rotation(1) == extra_before and sk2.get_bone_pose_position(0).y > 0.3,
		"partial skeleton: unknown bone untouched, known bones driven")
	# Drop the script's graph references: the character keeps its graph alive.
	var g2 := SmgGraph.new()
	g2.load("res://default.smg")
	var c2 := SmgCharacter.new()
	c2.graph = g2
	root.add_child(c2)
	c2.set_path(PackedVector3Array([Vector3(5, 0, 0), Vector3(5, 0, 5)]))
	g2 = null
	await frames(10)
	check(c2.get_time() > 0.2 and c2.graph != null, "character keeps its graph alive")
	# Unset the graph while running, then free in the "wrong" order.
	c2.graph = null
	check(c2.step(0.1) != OK, "graph unset -> step errors")
	c2.free()
	var c3 := SmgCharacter.new()
	c3.graph = g
	scene.add_child(c3)
	scene.free()                            # frees c and c3 with their parent
	await frames(2)
	g = null
	check(true, "freeing nodes and graphs in any order did not crash")
	check(not is_instance_valid(c), "scene freed")


