# Drives the demo project (bindings/godot/demo) headless like a user: a
# left-button drag on the ground draws a path, T and S place a transition
# and a splice point under the mouse, right click removes one; then checks
# that the character got the path and the points and walks it. Run by
# run_test.sh on a copy of the demo; the last line is "demo: N passed, M failed".
extends SceneTree

const PLANNED := 7
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
	print("demo: %d passed, %d failed" % [passed, failed])
	quit(0 if failed == 0 else 1)


func screen_of(cam: Camera3D, p: Vector3) -> Vector2:
	return cam.unproject_position(p)


func mouse_button(pos: Vector2, button: MouseButton, pressed: bool) -> void:
	var e := InputEventMouseButton.new()
	e.button_index = button
	e.pressed = pressed
	e.position = pos
	e.global_position = pos
	Input.parse_input_event(e)


func mouse_move(pos: Vector2) -> void:
	var e := InputEventMouseMotion.new()
	e.position = pos
	e.global_position = pos
	e.button_mask = MOUSE_BUTTON_MASK_LEFT
	Input.parse_input_event(e)


func mouse_hover(pos: Vector2) -> void:
	var e := InputEventMouseMotion.new()
	e.position = pos
	e.global_position = pos
	Input.parse_input_event(e)


func key(code: Key) -> void:
	for pressed in [true, false]:
		var e := InputEventKey.new()
		e.keycode = code
		e.physical_keycode = code
		e.pressed = pressed
		Input.parse_input_event(e)


func run() -> void:
	var main: Node3D = load("res://main.tscn").instantiate()
	root.add_child(main)
	await process_frame
	await process_frame
	var c: SmgCharacter = main.get_node("Body/Character")
	var cam: Camera3D = main.get_node("Camera3D")
	check(c.graph != null and c.graph.is_loaded() and c.get_child_count() > 0,
		"demo loaded the graph and built the skeleton")

	# Draw: press at the first point, drag through the rest, release.
	var pts := [Vector3(0, 0, 0.5), Vector3(0, 0, 2), Vector3(0.5, 0, 3.5), Vector3(1.5, 0, 5), Vector3(3, 0, 6)]
	mouse_button(screen_of(cam, pts[0]), MOUSE_BUTTON_LEFT, true)
	await process_frame
	for i in range(1, pts.size()):
		for k in range(1, 6):
			mouse_move(screen_of(cam, pts[i - 1].lerp(pts[i], k / 5.0)))
			await process_frame
	mouse_button(screen_of(cam, pts[-1]), MOUSE_BUTTON_LEFT, false)
	await process_frame
	var drawn := 0.0
	for i in range(1, pts.size()):
		drawn += pts[i - 1].distance_to(pts[i])
	check(abs(c.get_path_length() - drawn) < 0.5, "drag drew a %.2f m path (drawn %.2f m)" % [c.get_path_length(), drawn])

	# Points under the mouse: a splice, a transition, and one removed again.
	var markers: Node3D = main.get_node("Markers")
	mouse_hover(screen_of(cam, Vector3(0, 0, 1.5)))
	await process_frame
	key(KEY_S)
	mouse_hover(screen_of(cam, Vector3(1.5, 0, 5)))
	await process_frame
	key(KEY_T)
	mouse_hover(screen_of(cam, Vector3(3, 0, 6)))
	await process_frame
	key(KEY_S)
	await process_frame
	check(markers.get_child_count() == 3, "T/S placed 3 points (%d)" % markers.get_child_count())
	mouse_button(screen_of(cam, Vector3(3, 0, 6)), MOUSE_BUTTON_RIGHT, true)
	await process_frame
	await process_frame                       # queue_free happens at frame end
	check(markers.get_child_count() == 2, "right click removed the nearest point (%d left)" % markers.get_child_count())

	var actions: Array = []
	c.action_changed.connect(func(a, _n): actions.append(a))
	var start := c.global_position
	var worst := 0.0
	for i in 150:
		await process_frame
		if not c.is_path_end_reached():     # afterwards it walks on: not path following
			worst = max(worst, c.get_path_error())
	check(c.global_position.distance_to(start) > 2.0, "character walks the drawn path (%.2f m)" % c.global_position.distance_to(start))
	check(worst < 1.0, "character stays on the drawn path (at most %.2f m off)" % worst)
	check(actions.size() > 0, "the splice point changed the action: %s" % [actions])
