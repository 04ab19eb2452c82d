/*
 * bake_contacts.h - per-frame foot contacts and gait phase of one pool
 * clip (bake_contacts.c).
 */
#ifndef BAKE_CONTACTS_H
#define BAKE_CONTACTS_H

#include <stdint.h>

#include "bake_state.h"

void smgb_contacts_clip(smgb_bake* b, uint32_t clip);

#endif /* BAKE_CONTACTS_H */
