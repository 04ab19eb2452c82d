/* smg_gd_docs.h - the extension's class reference for the editor's help. */
#ifndef SMG_GD_DOCS_H
#define SMG_GD_DOCS_H

#include "gd_api.h"

/* Call at the EDITOR initialization level (the editor's help exists). */
void smg_gd_docs_load(void);

#endif
