## Simple visible bones for a skeleton made by SmgGraph.build_skeleton():
## one capsule per parent->child segment and a sphere for the head, attached
## with BoneAttachment3D so they follow the pose libsmg writes.
extends RefCounted


static func add_to(skel: Skeleton3D, graph: SmgGraph, color := Color(0.85, 0.55, 0.3)) -> void:
	var mat := StandardMaterial3D.new()
	mat.albedo_color = color
	var upper_mat := StandardMaterial3D.new()
	upper_mat.albedo_color = color.lerp(Color(0.3, 0.45, 0.9), 0.6)
	var attachments := {}
	for j in skel.get_bone_count():
		var parent := skel.get_bone_parent(j)
		if parent < 0:
			continue
		var offset: Vector3 = skel.get_bone_rest(j).origin
		var length := offset.length()
		if length < 0.02:
			continue
		if not attachments.has(parent):
			var att := BoneAttachment3D.new()
			att.bone_name = skel.get_bone_name(parent)
			skel.add_child(att)
			attachments[parent] = att
		var capsule := CapsuleMesh.new()
		capsule.radius = clamp(length * 0.18, 0.025, 0.06)
		capsule.height = max(length, capsule.radius * 2.0)
		var mi := MeshInstance3D.new()
		mi.mesh = capsule
		# Upper body (spine and arms) in another colour, so spliced actions show.
		var bname := skel.get_bone_name(j)
		var is_upper := bname.contains("Spine") or bname.contains("Arm") or bname.contains("Hand") \
			or bname.contains("Neck") or bname.contains("Head") or bname.contains("Shoulder") \
			or bname.contains("Finger") or bname.contains("Thumb")
		mi.material_override = upper_mat if is_upper else mat
		# Capsules are along +Y: turn +Y onto the offset direction.
		var dir := offset / length
		var axis := Vector3.UP.cross(dir)
		var basis := Basis()
		if axis.length() > 1e-5:
			basis = Basis(axis.normalized(), Vector3.UP.angle_to(dir))
		elif dir.y < 0.0:
			basis = Basis(Vector3.RIGHT, PI)
		mi.transform = Transform3D(basis, offset * 0.5)
		attachments[parent].add_child(mi)
	var head := skel.find_bone("Head")
	if head >= 0:
		var att := BoneAttachment3D.new()
		att.bone_name = "Head"
		skel.add_child(att)
		var sphere := SphereMesh.new()
		sphere.radius = 0.11
		sphere.height = 0.22
		var mi := MeshInstance3D.new()
		mi.mesh = sphere
		mi.material_override = upper_mat
		mi.position = Vector3(0, 0.08, 0)
		att.add_child(mi)
