/* smg_gd_docs.c - the class reference (the XML files in doc_classes/,
 * compiled in by tools/gen_docs.py) handed to the editor's help, so F1 and
 * the inspector tooltips document SmgGraph, SmgCharacter,
 * SmgSkeletonModifier and SmgGraphLoader like built-in classes. */
#include <stdint.h>

#include "smg_gd_docs.h"
#include "smg_gd_docs_gen.h"

void smg_gd_docs_load(void) {
	/* Optional: a Godot without editor help has no use for the docs. */
	if (!gd.editor_help_load_xml_from_utf8_chars_and_len) return;
	for (size_t i = 0; i < sizeof smg_gd_docs / sizeof smg_gd_docs[0]; i++)
		gd.editor_help_load_xml_from_utf8_chars_and_len(smg_gd_docs[i].xml, smg_gd_docs[i].size);
}
