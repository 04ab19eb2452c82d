## libsmg demo: draw a path on the ground and the character follows it with
## motion from the baked graph; place transition (lower body style) and
## splice (upper body action) points along the path.
##
##   left mouse, drag   draw a new path (the character rejoins it at once)
##   T                  transition point at the mouse: next style
##   S                  splice point at the mouse: next action
##   right mouse        remove the nearest transition/splice point
##   C                  clear the path      I  toggle foot IK
##
## Run with `-- --screenshot=FILE.png` to draw a fixed path, let the character
## walk it, save one frame and quit (make godot-screenshot).
extends Node3D

const BoneMeshes = preload("res://bone_meshes.gd")
const MIN_POINT_SPACING := 0.25  # metres between recorded mouse points
const BODY_GLTF := "res://body.gltf"

@onready var character: SmgCharacter = $Character
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


func _ready() -> void:
	help.text = "Left drag: draw a path   T: transition (next style) at mouse   " \
		+ "S: splice (next action) at mouse\nRight click: remove nearest point   C: clear path   I: toggle IK"
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
	var m: ImmediateMesh = path_mesh.mesh
	m.clear_surfaces()
	if points.size() < 2:
		return
	# A flat ribbon is visible from the camera where a 1-pixel line is not.
	m.surface_begin(Mesh.PRIMITIVE_TRIANGLE_STRIP)
	for i in points.size():
		var a := points[max(i - 1, 0)]
		var b := points[min(i + 1, points.size() - 1)]
		var side := (b - a).cross(Vector3.UP).normalized() * 0.06
		m.surface_add_vertex(points[i] + side + Vector3(0, 0.02, 0))
		m.surface_add_vertex(points[i] - side + Vector3(0, 0.02, 0))
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

func _screenshot(out: String) -> void:
	var pts: Array[Vector3] = [Vector3(0, 0, 0), Vector3(0, 0, 3), Vector3(1, 0, 5), Vector3(3, 0, 6), Vector3(5, 0, 6.5),
		Vector3(6.5, 0, 5.5), Vector3(7, 0, 3), Vector3(6.5, 0, 0)]
	_start_path(pts[0])
	for i in range(1, pts.size()):
		var seg_len := pts[i - 1].distance_to(pts[i])
		var n := int(ceil(seg_len / 0.5))
		for k in range(1, n + 1):
			_extend_path(pts[i - 1].lerp(pts[i], float(k) / n))
	_add_marker("S", Vector3(0.5, 0, 4))
	_add_marker("T", Vector3(5, 0, 6.5))
	camera.transform = Transform3D(Basis(), Vector3(2.6, 2.3, 9.2)).looking_at(Vector3(2.6, 0.6, 4.2), Vector3.UP)
	for i in 150:
		await get_tree().process_frame
	await RenderingServer.frame_post_draw
	var img := get_viewport().get_texture().get_image()
	var err := img.save_png(out)
	print("screenshot: ", out, " err=", err, " size=", img.get_size(), " driver=",
		RenderingServer.get_current_rendering_driver_name())
	get_tree().quit(0 if err == OK else 1)
