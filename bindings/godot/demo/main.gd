## libsmg demo: draw a path on the ground and the character follows it with
## motion from the baked graph; place transition (lower body style) and
## splice (upper body action) points along the path. The character is moved
## by its CharacterBody3D (engine-mover mode): walk it into the wall and it
## slides along. Footsteps leave marks, the walked track is drawn.
##
##   left mouse, drag   draw a new path (the character rejoins it at once)
##   T                  transition point at the mouse: next style
##   S                  splice point at the mouse: next action
##   right mouse        remove the nearest transition/splice point
##   C                  clear the path      I  toggle foot IK
##
## Run with `-- --screenshot=FILE.png` for a scripted sequence (a drawn path,
## a stop, then a new path behind the character that runs into the wall),
## one frame saved, then quit (make godot-screenshot).
extends Node3D

const BoneMeshes = preload("res://bone_meshes.gd")
const MIN_POINT_SPACING := 0.25  # metres between recorded mouse points
const BODY_GLTF := "res://body.gltf"

@onready var body: CharacterBody3D = $Body
@onready var character: SmgCharacter = $Body/Character
@onready var camera: Camera3D = $Camera3D
@onready var path_mesh: MeshInstance3D = $PathMesh
@onready var markers_root: Node3D = $Markers
@onready var help: Label = $UI/Help
@onready var status: Label = $UI/Status

var graph: SmgGraph
var points := PackedVector3Array()
var drawing := false
var markers: Array = []  # {id, kind ("T"/"S"), distance, value, node}
var next_style := 1
var next_action := 1
var last_event := ""
var track := PackedVector3Array()   # where the body went, for the track line
var footprints: Array = []          # the last footstep marks
var track_mesh := MeshInstance3D.new()
const MAX_FOOTPRINTS := 40


func _ready() -> void:
	help.text = "Left drag: draw a path   T: transition (next style) at mouse   " \
		+ "S: splice (next action) at mouse\nRight click: remove nearest point   C: clear path   I: toggle IK\n" \
		+ "The body is moved by its CharacterBody3D: walk into the wall and it slides"
	graph = character.graph
	if graph == null or not graph.is_loaded():
		status.text = "No graph loaded: run `make godot-demo` to copy build/default.smg here."
		return
	var skel := _add_body()
	# Apply the pose in the skeleton's modifier stage (Godot 4.3+ style);
	# without it the character writes the bone poses itself.
	skel.add_child(SmgSkeletonModifier.new())
	character.style_changed.connect(func(_s, n): last_event = "style -> " + n)
	character.action_changed.connect(func(_a, n): last_event = "action -> " + n)
	character.path_end_reached.connect(func(): last_event = "path end reached")
	character.constraint_reached.connect(func(id, _v, splice):
		last_event = "%s point %d reached" % ["splice" if splice else "transition", id])
	character.footstep.connect(_on_footstep)
	var track_mat := StandardMaterial3D.new()
	track_mat.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
	track_mat.albedo_color = Color(0.2, 0.9, 1.0)
	track_mesh.material_override = track_mat
	track_mesh.mesh = ImmediateMesh.new()
	track_mesh.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	add_child(track_mesh)
	var line_mat := StandardMaterial3D.new()
	line_mat.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
	line_mat.albedo_color = Color(1, 1, 0.2)
	path_mesh.material_override = line_mat
	path_mesh.mesh = ImmediateMesh.new()
	for arg in OS.get_cmdline_user_args():
		if arg.begins_with("--screenshot="):
			_screenshot(arg.trim_prefix("--screenshot="))


func _process(_delta: float) -> void:
	if graph == null or not graph.is_loaded():
		return
	status.text = "style: %s   action: %s   along path: %.1f / %.1f m   off path: %.2f m   IK: %s   %s" % [
		graph.get_style_name(character.style), graph.get_action_name(character.action),
		character.get_path_distance(), character.get_path_length(), character.get_path_error(),
		"on" if character.ik_enabled else "off", last_event]


# The engine's mover: the character steps here (it is not active), its
# root motion goes through move_and_slide, and where the body ended up
# (against the wall) goes back to the character.
func _physics_process(delta: float) -> void:
	if graph == null or not graph.is_loaded():
		return
	character.step(delta)
	body.velocity = character.get_root_motion() / delta
	body.velocity.y = 0.0
	body.move_and_slide()
	body.rotation.y += character.get_root_motion_yaw()
	character.set_ground_position(body.global_position, body.rotation.y)
	if track.is_empty() or track[track.size() - 1].distance_to(body.global_position) > 0.05:
		track.append(body.global_position)
		_draw_ribbon(track_mesh.mesh, track, 0.02, 0.025)  # narrower, above the path ribbons


func _on_footstep(_foot: int, pos: Vector3, _strength: float) -> void:
	var mark := MeshInstance3D.new()
	var disc := CylinderMesh.new()
	disc.top_radius = 0.07
	disc.bottom_radius = 0.07
	disc.height = 0.01
	mark.mesh = disc
	mark.position = Vector3(pos.x, 0.01, pos.z)
	mark.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	add_child(mark)
	footprints.append(mark)
	if footprints.size() > MAX_FOOTPRINTS:
		footprints.pop_front().queue_free()


func _unhandled_input(event: InputEvent) -> void:
	if graph == null or not graph.is_loaded():
		return
	if event is InputEventMouseButton and event.button_index == MOUSE_BUTTON_LEFT:
		drawing = event.pressed
		if event.pressed:
			var hit = _ground_at(event.position)
			if hit != null:
				_start_path(hit)
	elif event is InputEventMouseMotion and drawing:
		var hit = _ground_at(event.position)
		if hit != null:
			_extend_path(hit)
	elif event is InputEventMouseButton and event.button_index == MOUSE_BUTTON_RIGHT and event.pressed:
		var hit = _ground_at(event.position)
		if hit != null:
			_remove_marker_near(hit)
	elif event is InputEventKey and event.pressed and not event.echo:
		var mouse := get_viewport().get_mouse_position()
		match event.keycode:
			KEY_T:
				var hit = _ground_at(mouse)
				if hit != null:
					_add_marker("T", hit)
			KEY_S:
				var hit = _ground_at(mouse)
				if hit != null:
					_add_marker("S", hit)
			KEY_C:
				character.clear_path()
				character.clear_constraints()
				points.clear()
				_clear_markers()
				_redraw_path()
			KEY_I:
				character.ik_enabled = not character.ik_enabled


# --- the character's body --------------------------------------------------

# The skinned body `make godot-demo` generates from the graph's skeleton
# (build/smg-body-gltf: one mesh, bones named like the graph's joints),
# loaded at run time; without it, capsules on a skeleton built from the graph.
func _add_body() -> Skeleton3D:
	if FileAccess.file_exists(BODY_GLTF):
		var doc := GLTFDocument.new()
		var state := GLTFState.new()
		if doc.append_from_file(BODY_GLTF, state) == OK:
			var scene := doc.generate_scene(state)
			var found := scene.find_children("*", "Skeleton3D", true, false)
			if not found.is_empty():
				var skel: Skeleton3D = found[0]
				skel.get_parent().remove_child(skel)
				skel.owner = null
				for n in skel.find_children("*", "", true, false):
					n.owner = null
				scene.free()
				skel.name = "Skeleton3D"
				character.add_child(skel)
				return skel
			scene.free()
	push_warning("no generated body at %s (make godot-demo writes it): drawing capsules" % BODY_GLTF)
	var capsules := character.create_skeleton()
	BoneMeshes.add_to(capsules, graph)
	return capsules


# --- path drawing --------------------------------------------------------

func _ground_at(screen: Vector2):
	var from := camera.project_ray_origin(screen)
	var dir := camera.project_ray_normal(screen)
	return Plane(Vector3.UP, 0.0).intersects_ray(from, dir)


func _start_path(p: Vector3) -> void:
	points = PackedVector3Array([p])
	character.clear_constraints()
	_clear_markers()
	_redraw_path()


func _extend_path(p: Vector3) -> void:
	if points.size() > 0 and p.distance_to(points[points.size() - 1]) < MIN_POINT_SPACING:
		return
	points.append(p)
	if points.size() == 2:
		character.set_path(points)          # a path needs a direction: two points
	elif points.size() > 2:
		character.append_path_points(PackedVector3Array([p]))
	_redraw_path()


func _redraw_path() -> void:
	_draw_ribbon(path_mesh.mesh, points, 0.06, 0.02)


# A flat ribbon along pts: visible from the camera where a 1-pixel line is not.
func _draw_ribbon(m: ImmediateMesh, pts: PackedVector3Array, half_width: float, lift: float) -> void:
	m.clear_surfaces()
	if pts.size() < 2:
		return
	m.surface_begin(Mesh.PRIMITIVE_TRIANGLE_STRIP)
	for i in pts.size():
		var a := pts[max(i - 1, 0)]
		var b := pts[min(i + 1, pts.size() - 1)]
		var side := (b - a).cross(Vector3.UP).normalized() * half_width
		m.surface_add_vertex(pts[i] + side + Vector3(0, lift, 0))
		m.surface_add_vertex(pts[i] - side + Vector3(0, lift, 0))
	m.surface_end()


# Arc length along the drawn path of the point nearest to p, and that point.
func _project(p: Vector3) -> Array:
	var best := INF
	var best_s := 0.0
	var best_q := Vector3.ZERO
	var s := 0.0
	for i in range(points.size() - 1):
		var a := points[i]
		var ab := points[i + 1] - a
		var t: float = clamp((p - a).dot(ab) / max(ab.length_squared(), 1e-9), 0.0, 1.0)
		var q := a + ab * t
		if p.distance_to(q) < best:
			best = p.distance_to(q)
			best_s = s + ab.length() * t
			best_q = q
		s += ab.length()
	return [best_s, best_q]


# --- transition and splice points ----------------------------------------

func _add_marker(kind: String, p: Vector3) -> void:
	if points.size() < 2:
		return
	var pr := _project(p)
	var id: int
	var value: int
	if kind == "T":
		value = next_style % graph.get_style_count()
		id = character.add_transition(pr[0], value)
		next_style = value + 1
	else:
		value = next_action % graph.get_action_count()
		id = character.add_splice(pr[0], value)
		next_action = value + 1
	if id <= 0:
		return
	var node := Node3D.new()
	node.position = pr[1]
	var mi := MeshInstance3D.new()
	var cyl := CylinderMesh.new()
	cyl.top_radius = 0.12
	cyl.bottom_radius = 0.12
	cyl.height = 0.5
	mi.mesh = cyl
	mi.position.y = 0.25
	var mat := StandardMaterial3D.new()
	mat.albedo_color = Color(0.2, 0.6, 1.0) if kind == "T" else Color(1.0, 0.3, 0.3)
	mi.material_override = mat
	node.add_child(mi)
	var label := Label3D.new()
	label.text = graph.get_style_name(value) if kind == "T" else graph.get_action_name(value)
	label.billboard = BaseMaterial3D.BILLBOARD_ENABLED
	label.position.y = 0.8
	label.font_size = 48
	label.outline_size = 8
	node.add_child(label)
	markers_root.add_child(node)
	markers.append({"id": id, "kind": kind, "distance": pr[0], "value": value, "node": node})


func _remove_marker_near(p: Vector3) -> void:
	var best := -1
	for i in markers.size():
		if best < 0 or markers[i].node.position.distance_to(p) < markers[best].node.position.distance_to(p):
			best = i
	if best >= 0 and markers[best].node.position.distance_to(p) < 1.5:
		character.remove_constraint(markers[best].id)
		markers[best].node.queue_free()
		markers.remove_at(best)


func _clear_markers() -> void:
	for m in markers:
		m.node.queue_free()
	markers.clear()


# --- scripted run for the screenshot --------------------------------------

# Draws pts through the same code as a mouse drag (a point every 0.5 m).
func _draw_scripted(pts: Array) -> void:
	_start_path(pts[0])
	for i in range(1, pts.size()):
		var seg_len: float = pts[i - 1].distance_to(pts[i])
		var n := int(ceil(seg_len / 0.5))
		for k in range(1, n + 1):
			_extend_path(pts[i - 1].lerp(pts[i], float(k) / n))


# A drawn path with a splice point, the stop at its end, then a new path
# that starts behind the standing character and runs into the wall: the
# frame shows the first path (grey), the walked track (cyan), the footsteps
# and the character sliding along the wall on the second path (yellow).
func _screenshot(out: String) -> void:
	_draw_scripted([Vector3(0, 0, 0), Vector3(0, 0, 3), Vector3(-0.5, 0, 5)])
	_add_marker("S", Vector3(0, 0, 1.5))
	camera.transform = Transform3D(Basis(), Vector3(0.8, 7.0, 9.0)).looking_at(Vector3(0.8, 0.3, 1.8), Vector3.UP)
	var ended := [false]
	character.path_end_reached.connect(func(): ended[0] = true, CONNECT_ONE_SHOT)
	for i in 600:
		await get_tree().physics_frame
		if ended[0]:
			break
	for i in 60:  # stand for a second
		await get_tree().physics_frame
	var first := MeshInstance3D.new()
	first.mesh = ImmediateMesh.new()
	_draw_ribbon(first.mesh, points, 0.06, 0.02)
	var grey := StandardMaterial3D.new()
	grey.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
	grey.albedo_color = Color(0.65, 0.65, 0.65)
	first.material_override = grey
	add_child(first)
	_draw_scripted([body.global_position + Vector3(0.2, 0, -0.8), Vector3(1.2, 0, 2.0), Vector3(2.4, 0, -1.5)])
	var blocked := 0
	for i in 480:
		await get_tree().physics_frame
		if body.get_slide_collision_count() > 0:
			blocked += 1
		if blocked > 45:  # sliding along the wall for a while
			break
	await RenderingServer.frame_post_draw
	var img := get_viewport().get_texture().get_image()
	var err := img.save_png(out)
	print("screenshot: ", out, " err=", err, " size=", img.get_size(), " driver=",
		RenderingServer.get_current_rendering_driver_name(), " blocked physics frames: ", blocked,
		" along path 2: %.1f m, off it %.2f m" % [character.get_path_distance(), character.get_path_error()])
	get_tree().quit(0 if err == OK else 1)
