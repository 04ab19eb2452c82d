/*
 * bake_roles.c - body roles recognised from joint names (bake_roles.h).
 *
 * A joint name is split into words: at '_', '.', '-', ' ' (after dropping
 * an "ns:" namespace), at camelCase boundaries ("LeftUpLeg" -> Left Up
 * Leg, "LHipJoint" -> L Hip Joint) and around digit runs ("Spine1" ->
 * Spine 1). A word Left/Right/L/R (any case) is the side; digit words and
 * rig prefixes (mixamorig, Bip, VRoid's J_Bip_C_, Character1_, DEF-) are
 * dropped; the remaining words, lower
 * case and concatenated, form the *core* ("upleg", "upperleg", "toebase")
 * that the synonym tables below match. Synonyms are listed in order of
 * preference, so a rig with both "LeftUpLeg" and a helper "LHipJoint"
 * (CMU) takes the former; among equal matches the joint closest to the
 * root wins (Spine before Spine1, Neck before Neck1).
 */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bake_import_util.h"
#include "bake_roles.h"

#define MAX_WORDS 16
#define SIDE_NONE 0
#define SIDE_LEFT 1
#define SIDE_RIGHT 2

static const char* const k_role_names[SMGB_ROLE_COUNT] = {
    "pelvis",          "spine_base",      "neck",
    "head",            "left_upper_leg",  "left_lower_leg",
    "left_foot",       "left_toes",       "right_upper_leg",
    "right_lower_leg", "right_foot",      "right_toes",
    "left_upper_arm",  "left_lower_arm",  "left_hand",
    "right_upper_arm", "right_lower_arm", "right_hand",
    "left_shoulder",   "right_shoulder",  "left_fingers",
    "right_fingers"};

const char* smgb_role_name(smgb_role role) {
  return (int)role >= 0 && role < SMGB_ROLE_COUNT ? k_role_names[role] : "?";
}

int smgb_role_from_name(const char* name) {
  int i;
  if (!name) return -1;
  for (i = 0; i < SMGB_ROLE_COUNT; ++i)
    if (strcmp(name, k_role_names[i]) == 0) return i;
  return -1;
}

smgb_role smgb_role_counterpart(smgb_role role) {
  const char* n = smgb_role_name(role);
  char other[32];
  int k;
  if (strncmp(n, "left_", 5) == 0)
    snprintf(other, sizeof other, "right_%s", n + 5);
  else if (strncmp(n, "right_", 6) == 0)
    snprintf(other, sizeof other, "left_%s", n + 6);
  else
    return role;
  k = smgb_role_from_name(other);
  return k >= 0 ? (smgb_role)k : role;
}

/* ---- words of a joint name ---------------------------------------------- */

typedef struct name_words {
  const char* base;            /* the name after any "ns:" prefix */
  uint32_t count;
  uint32_t start[MAX_WORDS], len[MAX_WORDS];
} name_words;

static const char* strip_namespace(const char* name) {
  const char* c = strrchr(name, ':');
  return c ? c + 1 : name;
}

static int is_sep(char c) {
  return c == '_' || c == '.' || c == '-' || c == ' ' || c == '\t';
}

static void split_words(const char* name, name_words* w) {
  const char* s = strip_namespace(name);
  size_t i = 0, n = strlen(s);
  w->base = s;
  w->count = 0;
  while (i < n && w->count < MAX_WORDS) {
    size_t b;
    while (i < n && is_sep(s[i])) ++i;
    if (i >= n) break;
    b = i++;
    if (isdigit((unsigned char)s[b])) {
      while (i < n && isdigit((unsigned char)s[i])) ++i;
    } else {
      while (i < n && !is_sep(s[i]) && !isdigit((unsigned char)s[i])) {
        unsigned char p = (unsigned char)s[i - 1], c = (unsigned char)s[i];
        /* "upLeg": lower -> upper starts a word; "LHip": the last upper of
         * an upper-case run starts a word when a lower-case letter
         * follows. */
        if (isupper(c) && islower(p)) break;
        if (isupper(c) && isupper(p) && i + 1 < n &&
            islower((unsigned char)s[i + 1]))
          break;
        ++i;
      }
    }
    w->start[w->count] = (uint32_t)b;
    w->len[w->count] = (uint32_t)(i - b);
    w->count++;
  }
}

static int word_is(const name_words* w, uint32_t k, const char* lower) {
  uint32_t i;
  if (strlen(lower) != w->len[k]) return 0;
  for (i = 0; i < w->len[k]; ++i)
    if (tolower((unsigned char)w->base[w->start[k] + i]) != lower[i]) return 0;
  return 1;
}

static int word_side(const name_words* w, uint32_t k) {
  if (word_is(w, k, "left") || word_is(w, k, "l")) return SIDE_LEFT;
  if (word_is(w, k, "right") || word_is(w, k, "r")) return SIDE_RIGHT;
  return SIDE_NONE;
}

/* Words rigs put around the body-part name: Mixamo "mixamorig", 3ds Max
 * "Bip01", VRoid "J_Bip_C_/L_/R_", HumanIK "Character1_", Rigify "DEF-",
 * "ORG-". */
static int rig_prefix(const name_words* w, uint32_t k) {
  static const char* const words[] = {"mixamorig", "bip", "j", "c",
                                      "character", "def", "org"};
  size_t i;
  for (i = 0; i < sizeof words / sizeof words[0]; ++i)
    if (word_is(w, k, words[i])) return 1;
  return 0;
}

/* Side and core of a name ("mixamorig:LeftUpLeg" -> left, "upleg"). */
static int name_core(const char* name, char* core, size_t size) {
  name_words w;
  uint32_t k, used = 0;
  int side = SIDE_NONE;
  split_words(name, &w);
  core[0] = '\0';
  for (k = 0; k < w.count; ++k) {
    uint32_t i;
    int s = word_side(&w, k);
    if (s != SIDE_NONE && side == SIDE_NONE) {
      side = s;
      continue;
    }
    if (isdigit((unsigned char)w.base[w.start[k]]) || rig_prefix(&w, k))
      continue;
    for (i = 0; i < w.len[k] && used + 1 < size; ++i)
      core[used++] = (char)tolower((unsigned char)w.base[w.start[k] + i]);
  }
  core[used] = '\0';
  return side;
}

int smgb_roles_counterpart_name(const char* name, char out[SMGB_NAME_MAX]) {
  static const char* const swap[2][2] = {{"left", "right"}, {"l", "r"}};
  name_words w;
  uint32_t k;
  out[0] = '\0';
  if (!name) return 0;
  split_words(name, &w);
  for (k = 0; k < w.count; ++k) {
    int side = word_side(&w, k), form, upper_first, all_upper;
    const char* word;
    char repl[8];
    size_t i, pre, n;
    if (side == SIDE_NONE) continue;
    form = w.len[k] == 1 ? 1 : 0;
    word = swap[form][side == SIDE_LEFT ? 1 : 0];
    upper_first = isupper((unsigned char)w.base[w.start[k]]) != 0;
    all_upper = upper_first && w.len[k] > 1 &&
                isupper((unsigned char)w.base[w.start[k] + 1]);
    for (i = 0; word[i]; ++i)
      repl[i] = (char)((all_upper || (i == 0 && upper_first))
                           ? toupper((unsigned char)word[i])
                           : word[i]);
    repl[i] = '\0';
    pre = (size_t)(w.base - name) + w.start[k];
    n = pre + strlen(repl) + strlen(name + pre + w.len[k]);
    if (n >= SMGB_NAME_MAX) return 0;
    snprintf(out, SMGB_NAME_MAX, "%.*s%s%s", (int)pre, name, repl,
             name + pre + w.len[k]);
    return 1;
  }
  return 0;
}

/* ---- recognition ---------------------------------------------------------- */

/* Synonyms per role kind, most specific first. */
typedef struct role_kind {
  const char* const* synonyms;
  int sided;
} role_kind;

static const char* const k_pelvis[] = {"hips", "pelvis", "hip", NULL};
static const char* const k_neck[] = {"neck", NULL};
static const char* const k_head[] = {"head", NULL};
static const char* const k_upper_leg[] = {"upleg", "upperleg", "thigh",
                                          "legupper", "femur", "hip", NULL};
static const char* const k_lower_leg[] = {"leg",  "lowerleg", "knee",
                                          "calf", "shin",     "leglower",
                                          "lowleg", "shank",  NULL};
static const char* const k_foot[] = {"foot", "ankle", NULL};
static const char* const k_toes[] = {"toebase", "toes", "toe", "ball",
                                     NULL};
static const char* const k_upper_arm[] = {"arm", "upperarm", "uparm",
                                          "armupper", "humerus", NULL};
static const char* const k_lower_arm[] = {"forearm", "lowerarm", "elbow",
                                          "armlower", "lowarm", NULL};
static const char* const k_hand[] = {"hand", "wrist", NULL};
static const char* const k_shoulder[] = {"shoulder", "clavicle", "collar",
                                         NULL};
static const char* const k_fingers[] = {"handindex", "indexproximal",
                                        "index", "handmiddle",
                                        "middleproximal", NULL};

/* Synonyms of each role (NULL: found structurally, not by name). */
static const char* const* role_synonyms(int role) {
  switch (role) {
    case SMGB_ROLE_PELVIS: return k_pelvis;
    case SMGB_ROLE_NECK: return k_neck;
    case SMGB_ROLE_HEAD: return k_head;
    case SMGB_ROLE_LEFT_UPPER_LEG: case SMGB_ROLE_RIGHT_UPPER_LEG: return k_upper_leg;
    case SMGB_ROLE_LEFT_LOWER_LEG: case SMGB_ROLE_RIGHT_LOWER_LEG: return k_lower_leg;
    case SMGB_ROLE_LEFT_FOOT: case SMGB_ROLE_RIGHT_FOOT: return k_foot;
    case SMGB_ROLE_LEFT_TOES: case SMGB_ROLE_RIGHT_TOES: return k_toes;
    case SMGB_ROLE_LEFT_UPPER_ARM: case SMGB_ROLE_RIGHT_UPPER_ARM: return k_upper_arm;
    case SMGB_ROLE_LEFT_LOWER_ARM: case SMGB_ROLE_RIGHT_LOWER_ARM: return k_lower_arm;
    case SMGB_ROLE_LEFT_HAND: case SMGB_ROLE_RIGHT_HAND: return k_hand;
    case SMGB_ROLE_LEFT_SHOULDER: case SMGB_ROLE_RIGHT_SHOULDER: return k_shoulder;
    case SMGB_ROLE_LEFT_FINGERS: case SMGB_ROLE_RIGHT_FINGERS: return k_fingers;
    default: return NULL;
  }
}

static int role_side(int role) {
  const char* n = k_role_names[role];
  if (strncmp(n, "left_", 5) == 0) return SIDE_LEFT;
  if (strncmp(n, "right_", 6) == 0) return SIDE_RIGHT;
  return SIDE_NONE;
}

static uint32_t depth_of(const smgb_skeleton* s, uint32_t j) {
  uint32_t d = 0;
  int32_t p = s->parents[j];
  while (p >= 0 && d <= s->joint_count) {
    ++d;
    p = s->parents[p];
  }
  return d;
}

static int is_ancestor(const smgb_skeleton* s, int32_t a, int32_t j) {
  uint32_t guard = 0;
  if (a < 0 || j < 0) return 0;
  while (j >= 0 && guard++ <= s->joint_count) {
    if (j == a) return 1;
    j = s->parents[j];
  }
  return 0;
}

/* Strict ancestor: a above j, a != j. */
static int is_above(const smgb_skeleton* s, int32_t a, int32_t j) {
  return a >= 0 && j >= 0 && a != j && is_ancestor(s, a, j);
}

static void recognise_by_name(const smgb_skeleton* s, smgb_roles* out) {
  uint32_t best_rank[SMGB_ROLE_COUNT], best_depth[SMGB_ROLE_COUNT];
  uint32_t j;
  int r;
  for (r = 0; r < SMGB_ROLE_COUNT; ++r) {
    out->joint[r] = -1;
    best_rank[r] = best_depth[r] = UINT32_MAX;
  }
  for (j = 0; j < s->joint_count; ++j) {
    char core[SMGB_NAME_MAX];
    int side = name_core(s->names[j], core, sizeof core);
    uint32_t depth = depth_of(s, j);
    for (r = 0; r < SMGB_ROLE_COUNT; ++r) {
      const char* const* syn = role_synonyms(r);
      uint32_t k;
      if (!syn || role_side(r) != side) continue;
      for (k = 0; syn[k]; ++k) {
        if (strcmp(core, syn[k]) != 0) continue;
        if (k < best_rank[r] || (k == best_rank[r] && depth < best_depth[r])) {
          best_rank[r] = k;
          best_depth[r] = depth;
          out->joint[r] = (int32_t)j;
        }
        break;
      }
    }
  }
}

/* Lowest common ancestor of a and b (-1 if either is -1). */
static int32_t common_ancestor(const smgb_skeleton* s, int32_t a, int32_t b) {
  if (a < 0 || b < 0) return -1;
  for (; a >= 0; a = s->parents[a])
    if (is_ancestor(s, a, b)) return a;
  return -1;
}

/* Pelvis and spine base from the structure: the pelvis is a named
 * hips/pelvis joint when it is above both legs, else the lowest common
 * ancestor of the legs and the head; the spine base is the pelvis child on
 * the way to the neck (or head). */
static void structural_roles(const smgb_skeleton* s, smgb_roles* r,
                             int pelvis_mapped) {
  int32_t l = r->joint[SMGB_ROLE_LEFT_UPPER_LEG];
  int32_t rt = r->joint[SMGB_ROLE_RIGHT_UPPER_LEG];
  int32_t top = r->joint[SMGB_ROLE_NECK] >= 0 ? r->joint[SMGB_ROLE_NECK]
                                              : r->joint[SMGB_ROLE_HEAD];
  int32_t p = r->joint[SMGB_ROLE_PELVIS];
  if (!pelvis_mapped && p >= 0 && l >= 0 && rt >= 0 &&
      !(is_above(s, p, l) && is_above(s, p, rt)))
    p = -1;
  if (p < 0 && !pelvis_mapped)
    p = common_ancestor(s, common_ancestor(s, l, rt), top);
  r->joint[SMGB_ROLE_PELVIS] = p;
  if (r->joint[SMGB_ROLE_SPINE_BASE] < 0 && p >= 0 && top >= 0 &&
      is_above(s, p, top)) {
    int32_t j = top;
    while (s->parents[j] != p) j = s->parents[j];
    r->joint[SMGB_ROLE_SPINE_BASE] = j;
  }
}

/* Drop name matches that contradict the chain order (a "foot" that is not
 * below the "lower leg"): better missing than wrong. */
static void check_chains(const smgb_skeleton* s, smgb_roles* r) {
  static const int chains[4][4] = {
      {SMGB_ROLE_LEFT_UPPER_LEG, SMGB_ROLE_LEFT_LOWER_LEG, SMGB_ROLE_LEFT_FOOT,
       SMGB_ROLE_LEFT_TOES},
      {SMGB_ROLE_RIGHT_UPPER_LEG, SMGB_ROLE_RIGHT_LOWER_LEG,
       SMGB_ROLE_RIGHT_FOOT, SMGB_ROLE_RIGHT_TOES},
      {SMGB_ROLE_LEFT_UPPER_ARM, SMGB_ROLE_LEFT_LOWER_ARM, SMGB_ROLE_LEFT_HAND,
       SMGB_ROLE_LEFT_FINGERS},
      {SMGB_ROLE_RIGHT_UPPER_ARM, SMGB_ROLE_RIGHT_LOWER_ARM,
       SMGB_ROLE_RIGHT_HAND, SMGB_ROLE_RIGHT_FINGERS}};
  int c, k;
  for (c = 0; c < 4; ++c)
    for (k = 1; k < 4; ++k)
      if (r->joint[chains[c][k]] >= 0 &&
          !is_above(s, r->joint[chains[c][k - 1]], r->joint[chains[c][k]]))
        r->joint[chains[c][k]] = -1;
}

void smgb_roles_guess(const smgb_skeleton* s, smgb_roles* out) {
  int r;
  if (!out) return;
  for (r = 0; r < SMGB_ROLE_COUNT; ++r) out->joint[r] = -1;
  if (!s || !s->names || !s->parents || s->joint_count == 0) return;
  recognise_by_name(s, out);
  check_chains(s, out);
  structural_roles(s, out, 0);
}

/* ---- bone maps -------------------------------------------------------------- */

/* Calls fn(role, joint) per "role=joint" line; returns 0 and fills err on
 * a syntax error or unknown role. */
typedef int (*bone_fn)(void* ctx, int role, const char* joint);

static int each_bone(const char* map, const char* source, smgb_error* err,
                     bone_fn fn, void* ctx) {
  const char* p = map;
  uint32_t entry = 0;
  if (!map) return 1;
  while (*p) {
    const char* e = p;
    const char *eq, *a, *b;
    char role[32], joint[SMGB_NAME_MAX];
    int r;
    while (*e && *e != '\n') ++e;
    ++entry;
    a = p;
    b = e;
    while (a < b && isspace((unsigned char)*a)) ++a;
    while (b > a && isspace((unsigned char)b[-1])) --b;
    p = *e ? e + 1 : e;
    if (a == b) continue;
    for (eq = a; eq < b && *eq != '='; ++eq) {
    }
    {
      const char* re = eq;
      const char* js = eq + 1;
      while (re > a && isspace((unsigned char)re[-1])) --re;
      while (js < b && isspace((unsigned char)*js)) ++js;
      if (eq == b || re == a || js >= b ||
          (size_t)(re - a) >= sizeof role ||
          (size_t)(b - js) >= sizeof joint) {
        smgb_imp_errorf(err,
                        "%s: bone map entry %u '%.*s' is not ROLE=JOINT "
                        "(a role name and a joint name of at most %d "
                        "characters)",
                        source, entry, (int)(b - a > 80 ? 80 : b - a), a,
                        SMGB_NAME_MAX - 1);
        return 0;
      }
      memcpy(role, a, (size_t)(re - a));
      role[re - a] = '\0';
      memcpy(joint, js, (size_t)(b - js));
      joint[b - js] = '\0';
    }
    r = smgb_role_from_name(role);
    if (r < 0) {
      smgb_imp_errorf(err,
                      "%s: bone map: unknown role '%s' (roles: pelvis, "
                      "spine_base, neck, head, left_/right_ upper_leg, "
                      "lower_leg, foot, toes, upper_arm, lower_arm, hand, "
                      "shoulder, fingers)",
                      source, role);
      return 0;
    }
    if (fn && !fn(ctx, r, joint)) return 0;
  }
  return 1;
}

smg_result smgb_bone_map_check(const char* map, const char* source,
                               smgb_error* err) {
  if (err) err->message[0] = '\0';
  if (!source) source = "(bone map)";
  return each_bone(map, source, err, NULL, NULL) ? SMG_OK
                                                 : SMG_ERROR_INVALID_ARGUMENT;
}

typedef struct map_ctx {
  const smgb_skeleton* s;
  smgb_roles* mapped;
  const char* source;
  smgb_error* err;
} map_ctx;

static int apply_bone(void* vctx, int role, const char* joint) {
  map_ctx* c = (map_ctx*)vctx;
  int32_t j = smgb_skeleton_find(c->s, joint);
  if (j < 0) {
    smgb_imp_errorf(c->err,
                    "%s: bone map names joint '%s' for role '%s', but the "
                    "skeleton has no such joint",
                    c->source, joint, smgb_role_name((smgb_role)role));
    return 0;
  }
  c->mapped->joint[role] = j;
  return 1;
}

smg_result smgb_roles_find(const smgb_skeleton* s, const char* bone_map,
                           const char* source, smgb_roles* out,
                           smgb_error* err) {
  smgb_roles mapped, r;
  map_ctx ctx;
  int i, k;
  if (err) err->message[0] = '\0';
  if (!source) source = "(skeleton)";
  if (!s || !out || !s->names || !s->parents || s->joint_count == 0) {
    smgb_imp_errorf(err, "%s: invalid skeleton for role recognition", source);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  for (k = 0; k < SMGB_ROLE_COUNT; ++k) mapped.joint[k] = -1;
  ctx.s = s;
  ctx.mapped = &mapped;
  ctx.source = source;
  ctx.err = err;
  if (!each_bone(bone_map, source, err, apply_bone, &ctx))
    return SMG_ERROR_INVALID_ARGUMENT;
  /* Names first, the map overrides them, then the structural roles are
   * derived from the result (so a mapped leg moves the pelvis with it). */
  recognise_by_name(s, &r);
  for (k = 0; k < SMGB_ROLE_COUNT; ++k)
    if (mapped.joint[k] >= 0) r.joint[k] = mapped.joint[k];
  check_chains(s, &r);
  for (k = 0; k < SMGB_ROLE_COUNT; ++k)
    if (mapped.joint[k] >= 0 && r.joint[k] < 0) {
      smgb_imp_errorf(err,
                      "%s: bone map: role '%s' = '%s' is not below the "
                      "joint of the role before it in its limb",
                      source, smgb_role_name((smgb_role)k),
                      s->names[mapped.joint[k]]);
      return SMG_ERROR_INVALID_ARGUMENT;
    }
  structural_roles(s, &r, mapped.joint[SMGB_ROLE_PELVIS] >= 0);
  /* Report named roles before the structural ones (pelvis, spine base),
   * which are only missing because of them. */
  for (i = 0; i < SMGB_ROLE_REQUIRED_COUNT; ++i) {
    k = (i + 2) % SMGB_ROLE_REQUIRED_COUNT;
    if (r.joint[k] < 0) {
      smgb_imp_errorf(err,
                      "%s: no joint for the body role '%s' (recognised "
                      "naming: CMU, Bandai Namco, Mixamo, Godot, Unity/VRM, "
                      "thigh_l/thigh.L; name it with a manifest line "
                      "'bones %s=JOINT')",
                      source, smgb_role_name((smgb_role)k),
                      smgb_role_name((smgb_role)k));
      return SMG_ERROR_INVALID_ARGUMENT;
    }
  }
  *out = r;
  return SMG_OK;
}

float smgb_roles_leg_length(const smgb_skeleton* s, const smgb_roles* r) {
  int32_t hip, j;
  double len = 0.0;
  uint32_t guard = 0;
  if (!s || !r || !s->offsets || !s->parents) return 0.0f;
  hip = r->joint[SMGB_ROLE_LEFT_UPPER_LEG];
  j = r->joint[SMGB_ROLE_LEFT_FOOT];
  if (hip < 0 || j < 0 || !is_above(s, hip, j)) return 0.0f;
  /* Sum of bone lengths from the ankle up to the hip: independent of how
   * bent the rest pose is. */
  while (j != hip && guard++ <= s->joint_count) {
    const float* o = s->offsets[j];
    len += sqrt((double)o[0] * o[0] + (double)o[1] * o[1] +
                (double)o[2] * o[2]);
    j = s->parents[j];
  }
  return (float)len;
}

void smgb_roles_partners(const smgb_skeleton* s, const smgb_roles* r,
                         int32_t* partner) {
  uint32_t j;
  int k;
  if (!s || !partner || !s->names) return;
  for (j = 0; j < s->joint_count; ++j) {
    char other[SMGB_NAME_MAX];
    int32_t m = -1;
    if (smgb_roles_counterpart_name(s->names[j], other))
      m = smgb_skeleton_find(s, other);
    partner[j] = m >= 0 ? m : (int32_t)j;
  }
  /* Roles pair joints whose names carry no side (a bone map's names). */
  for (k = 0; r && k < SMGB_ROLE_COUNT; ++k) {
    int32_t a = r->joint[k];
    int32_t b = r->joint[smgb_role_counterpart((smgb_role)k)];
    if (a >= 0 && b >= 0 && a != b && partner[a] == a && partner[b] == b) {
      partner[a] = b;
      partner[b] = a;
    }
  }
  for (j = 0; j < s->joint_count; ++j)
    if (partner[partner[j]] != (int32_t)j) partner[j] = (int32_t)j;
}

float smgb_skeleton_leg_length(const smgb_skeleton* s) {
  smgb_roles r;
  if (!s || !s->names || !s->parents || !s->offsets) return 0.0f;
  smgb_roles_guess(s, &r);
  return smgb_roles_leg_length(s, &r);
}
