/*
 * tsan_shared_graph.c - the threading contract under ThreadSanitizer
 * (make tsan): one graph is shared by STEPPERS threads that each create,
 * drive and destroy their own characters on it (paths, appends,
 * constraints, style/action switches, IK toggles, steps, both pose
 * getters), while LOADERS other threads load, inspect and destroy other
 * graphs (from memory and from a file) and spawn short-lived characters
 * on them. The graph must be safe to share without locks; any data race
 * is a TSan report, which fails the run (exit status 66).
 *
 *   tsan_shared_graph [BLOB_FILE]   BLOB_FILE: a baked graph to share
 *                                   (default: the in-memory fixture)
 */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "blob.h"
#include "fixture_graph.h"
#include "smg.h"

enum { STEPPERS = 4, LOADERS = 2, ROUNDS = 3, STEPS = 150, LOADS = 12 };

static smg_graph* g_shared;
static void* g_fixture_blob;
static size_t g_fixture_size;
static const char* g_file;

static uint32_t xorshift(uint32_t* s) {
  *s ^= *s << 13;
  *s ^= *s >> 17;
  *s ^= *s << 5;
  return *s;
}

static int drive(smg_graph* g, uint32_t seed, uint32_t steps) {
  smg_graph_info info;
  smg_character_desc d;
  smg_character_state st;
  smg_character* ch = NULL;
  float xz[2 * 16], root[3], *rot, *mats;
  uint32_t i, k, id;
  int bad = 0;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  if (smg_graph_get_info(g, &info) != SMG_OK) return 1;
  rot = (float*)malloc(sizeof(float) * 4 * info.joint_count);
  mats = (float*)malloc(sizeof(float) * 16 * info.joint_count);
  memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.seed = seed;
  d.position[0] = (float)(seed % 7u);
  if (!rot || !mats || smg_character_create(g, &d, &ch) != SMG_OK) {
    free(rot);
    free(mats);
    return 1;
  }
  for (k = 0; k < 16; ++k) {
    xz[2 * k] = d.position[0] + 0.4f * (float)(xorshift(&seed) % 5u);
    xz[2 * k + 1] = 1.5f * (float)k;
  }
  bad |= smg_character_set_path(ch, xz, 8) != SMG_OK;
  bad |= smg_character_add_splice(ch, 3.0f, info.action_count - 1, &id) !=
         SMG_OK;
  bad |= smg_character_add_transition(ch, 6.0f, info.style_count - 1, &id) !=
         SMG_OK;
  memset(&st, 0, sizeof st);
  st.struct_size = sizeof st;
  for (i = 0; i < steps && !bad; ++i) {
    uint32_t r = xorshift(&seed) % 64u;
    if (r == 0) smg_character_append_path(ch, xz + 16, 8);
    if (r == 1) smg_character_set_style(ch, xorshift(&seed) % info.style_count);
    if (r == 2)
      smg_character_set_action(ch, xorshift(&seed) % info.action_count);
    if (r == 3) smg_character_set_ik(ch, xorshift(&seed) & 1u);
    bad |= smg_character_step(ch, (r == 4) ? 0.2f : 1.0f / 60.0f) != SMG_OK;
    bad |= smg_character_get_state(ch, &st) != SMG_OK;
    bad |= smg_character_get_local_pose(ch, root, rot, info.joint_count) !=
           SMG_OK;
    bad |= smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, mats,
                                            info.joint_count) != SMG_OK;
    bad |= !isfinite(root[0]) || !isfinite(mats[12]);
  }
  bad |= smg_character_destroy(ch) != SMG_OK;
  free(rot);
  free(mats);
  return bad;
}

static void* stepper(void* arg) {
  uint32_t seed = 0x9e37u + (uint32_t)(size_t)arg, r;
  int bad = 0;
  for (r = 0; r < ROUNDS; ++r) bad |= drive(g_shared, seed + 17u * r, STEPS);
  return (void*)(size_t)bad;
}

static void* loader(void* arg) {
  uint32_t i, seed = 0x51u + (uint32_t)(size_t)arg;
  int bad = 0;
  for (i = 0; i < LOADS; ++i) {
    smg_graph* g = NULL;
    smg_result r = (g_file && (i & 1u))
                       ? smg_graph_load_file(g_file, NULL, &g)
                       : smg_graph_load_memory(g_fixture_blob, g_fixture_size,
                                               NULL, &g);
    if (r != SMG_OK) {
      bad = 1;
      break;
    }
    bad |= drive(g, seed + i, 10);
    bad |= smg_graph_destroy(g) != SMG_OK;
  }
  return (void*)(size_t)bad;
}

int main(int argc, char** argv) {
  pthread_t t[STEPPERS + LOADERS];
  size_t i;
  int bad = 0;
  g_file = argc > 1 ? argv[1] : NULL;
  if (fixture_graph_blob(&g_fixture_blob, &g_fixture_size) != SMG_OK)
    return 1;
  if ((g_file ? smg_graph_load_file(g_file, NULL, &g_shared)
              : smg_graph_load_memory(g_fixture_blob, g_fixture_size, NULL,
                                      &g_shared)) != SMG_OK) {
    fprintf(stderr, "tsan: cannot load %s\n", g_file ? g_file : "fixture");
    return 1;
  }
  for (i = 0; i < STEPPERS + LOADERS; ++i)
    if (pthread_create(&t[i], NULL, i < STEPPERS ? stepper : loader,
                       (void*)i) != 0)
      return 1;
  for (i = 0; i < STEPPERS + LOADERS; ++i) {
    void* ret;
    pthread_join(t[i], &ret);
    bad |= ret != NULL;
  }
  bad |= smg_graph_destroy(g_shared) != SMG_OK;
  smgi_blob_free(g_fixture_blob, NULL);
  printf("tsan: %d stepper threads x %d characters x %d steps on one shared "
         "graph (%s), %d loader threads x %d graphs: %s\n",
         STEPPERS, ROUNDS, STEPS, g_file ? g_file : "fixture", LOADERS, LOADS,
         bad ? "API FAILURE" : "ok");
  return bad;
}
