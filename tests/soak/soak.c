/*
 * soak.c - many characters for many frames with random use (make soak;
 * a short run is part of make test). On each graph given, C characters
 * are stepped S times each with random path edits (new paths, appends,
 * clears), transitions and splices added/moved/removed, style and action
 * switches, IK toggles and dt jitter. Checked on every character-frame:
 *   - no non-finite value in the state, the local pose or the matrices;
 *   - the root never moves faster than the data's fastest motion allows
 *     (measured from the blob: the largest root speed between consecutive
 *     frames of any edge, x SOAK_SPEED_MARGIN, + SOAK_JUMP_SLACK);
 *   - while a path is set (characters get a new one 2 m before its end:
 *     stopping at the end is not this check's subject), the distance from
 *     the path stays under what committed motion can explain: paths start
 *     within SOAK_PATH_START of the character, and the planning horizon's
 *     committed motion (2 s by default) at the data's fastest speed can
 *     carry it that far from a path changed under it; more is divergence;
 *   - no allocator call between the last create and the first destroy
 *     (graph and characters use counting allocators);
 *   - with --instructions OUT (under callgrind, soak_count.h): the work
 *     of a step does not grow: the instructions of stepping all
 *     characters over the last window of the timed steps (--window W
 *     frames, default a tenth of them) are within 10 % of the first
 *     window's. The timed steps follow SOAK_SETTLE settling ones, and the
 *     random use starts in its steady mix, so both windows are the same
 *     kind of work. --grow G proves the check live: ballast characters
 *     stepped with the soak's add up to G more work by the end of the
 *     run, and the run passes only if the check catches that growth.
 * Prints one summary line per graph and one in total; exit status 1 on
 * any failed check.
 *
 *   soak [--characters C] [--steps S] [--seed N]
 *        [--instructions OUT [--window W] [--grow G]] GRAPH.smg...
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "blob.h"
#include "quat_pack.h"
#include "smg.h"
#include "soak_count.h"

#define SOAK_SPEED_MARGIN 1.5f /* blends, crossfades and IK move the root
                                  a little faster than any one frame pair */
#define SOAK_JUMP_SLACK 0.02f  /* metres per step */
#define SOAK_PATH_START 0.5f  /* metres: new paths start this close */
#define SOAK_HORIZON 2.0f      /* seconds: smg_character_desc's default */
#define SOAK_PATH_AHEAD 2.0f   /* metres of path kept ahead of a character */
/* Path curvature at most 0.04 rad per 0.5 m = 0.08 rad/m: the synthetic
 * run turns at 0.3 rad/s at 3.4 m/s (0.09 rad/m), and a path the data
 * cannot turn onto would make the path-error check grade the data, not
 * the runtime. */
#define SOAK_TURN 0.04f
#define SOAK_START_TURN 0.1f
#define SOAK_PATH_POINTS 48
#define SOAK_MAX_JOINTS 256
/* --instructions: steps before the timed run. All characters start at once,
 * from rest, on new paths: measured (instruction counts of 100 characters
 * per 100 frames, default graph), the first 100 frames are 40 % more work
 * than the steady state and the next 100 frames 10 %; 10 s settles it. */
#define SOAK_SETTLE 600
#define SOAK_STR_(x) #x
#define SOAK_STR(x) SOAK_STR_(x)

typedef struct counter {
  long allocs, frees;
} counter;

static void* count_alloc(size_t size, size_t align, void* user) {
  counter* c = (counter*)user;
  void* p = NULL;
  c->allocs++;
  if (align < sizeof(void*)) align = sizeof(void*);
  if (posix_memalign(&p, align, size ? size : 1) != 0) return NULL;
  return p;
}

static void count_free(void* p, void* user) {
  counter* c = (counter*)user;
  if (p) c->frees++;
  free(p);
}

static uint32_t g_rng = 1;
static uint32_t rnd(void) {
  g_rng ^= g_rng << 13;
  g_rng ^= g_rng >> 17;
  g_rng ^= g_rng << 5;
  return g_rng;
}
static float uni(float a, float b) {
  return a + (b - a) * (float)(rnd() % 1000001u) / 1000000.0f;
}

typedef struct soak_char {
  smg_character* ch;
  float root[3];
  float end_x, end_z, end_heading; /* where the path ends, for appends */
  uint32_t points, ids[8], nid;
} soak_char;

typedef struct soak_stats {
  long frames, nonfinite, jumps, path_errors;
  float max_speed, max_path_error, path_bound, data_speed;
  long allocs_after_create;
  double first, last; /* instructions of the steps in the two windows */
} soak_stats;

/* The data's fastest root motion: consecutive frames of every lower edge
 * (original clips and transitions), metres per second on the ground. */
static float data_max_speed(const void* blob, size_t size) {
  smgi_graph_data g;
  float best = 0.0f, a[3], b[3];
  uint32_t e, f;
  if (smgi_blob_read(blob, size, 0, &g, NULL, 0) != SMG_OK) return 0.0f;
  for (e = 0; e < g.lower_edge_count; ++e) {
    const smgi_edge* ed = &g.lower_edges[e];
    for (f = 0; f + 1 < ed->frame_count; ++f) {
      float dx, dz, v;
      smgi_pose_root(smgi_pose_record(&g, ed->first_frame + f), a);
      smgi_pose_root(smgi_pose_record(&g, ed->first_frame + f + 1), b);
      dx = b[0] - a[0];
      dz = b[2] - a[2];
      v = sqrtf(dx * dx + dz * dz) * g.info->frame_rate;
      if (v > best) best = v;
    }
  }
  return best;
}

static void* read_blob(const char* path, size_t* size) {
  FILE* f = fopen(path, "rb");
  void* p = NULL;
  long n;
  if (!f) return NULL;
  if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) > 0 &&
      fseek(f, 0, SEEK_SET) == 0 &&
      posix_memalign(&p, 16, (size_t)n) == 0) {
    if (fread(p, 1, (size_t)n, f) != (size_t)n) {
      free(p);
      p = NULL;
    }
    *size = (size_t)n;
  }
  fclose(f);
  return p;
}

/* A smooth random path from (x, z) heading h: segments of 0.5-1.5 m
 * turning at most SOAK_TURN rad each, starting within SOAK_START_TURN of
 * the character's heading: paths the data can follow. */
static uint32_t make_path(float* xz, uint32_t n, float x, float z,
                          float h) {
  uint32_t k;
  for (k = 0; k < n; ++k) {
    float step = uni(0.5f, 1.5f);
    xz[2 * k] = x;
    xz[2 * k + 1] = z;
    h += uni(-SOAK_TURN, SOAK_TURN);
    x += step * sinf(h);
    z += step * cosf(h);
  }
  return n;
}

static void new_path(soak_char* c, const smg_character_state* st) {
  float xz[2 * SOAK_PATH_POINTS];
  uint32_t n = 8 + rnd() % (SOAK_PATH_POINTS - 8);
  const float r = SOAK_PATH_START * 0.7f; /* per axis */
  make_path(xz, n, st->position[0] + uni(-r, r), st->position[2] + uni(-r, r),
            st->heading + uni(-SOAK_START_TURN, SOAK_START_TURN));
  if (smg_character_set_path(c->ch, xz, n) != SMG_OK) return;
  c->points = n;
  c->end_x = xz[2 * n - 2];
  c->end_z = xz[2 * n - 1];
  c->end_heading = atan2f(xz[2 * n - 2] - xz[2 * n - 4],
                          xz[2 * n - 1] - xz[2 * n - 3]);
}

static void append(soak_char* c) {
  float xz[2 * 8];
  uint32_t n = 1 + rnd() % 8, k;
  float x = c->end_x, z = c->end_z, h = c->end_heading;
  if (c->points + n > 500) return; /* the default capacity is 512 */
  for (k = 0; k < n; ++k) {
    float step = uni(0.5f, 1.5f);
    h += uni(-SOAK_TURN, SOAK_TURN);
    x += step * sinf(h);
    z += step * cosf(h);
    xz[2 * k] = x;
    xz[2 * k + 1] = z;
  }
  if (smg_character_append_path(c->ch, xz, n) != SMG_OK) return;
  c->points += n;
  c->end_x = x;
  c->end_z = z;
  c->end_heading = h;
}

/* n transitions and splices at random places on the path */
static void add_constraints(soak_char* c, uint32_t n,
                            const smg_graph_info* info) {
  float len = 0.0f;
  uint32_t id;
  smg_character_get_path_length(c->ch, &len);
  while (n-- && c->nid < 8) {
    smg_result r = rnd() % 2
        ? smg_character_add_transition(c->ch, uni(0, len),
                                       rnd() % info->style_count, &id)
        : smg_character_add_splice(c->ch, uni(0, len),
                                   rnd() % info->action_count, &id);
    if (r == SMG_OK) c->ids[c->nid++] = id;
  }
}

/* One random edit now and then: eleven kinds, each one in 1200 frames,
 * so about one edit every 2 s per character at 60 Hz. Constraints are
 * added (two kinds) as often as removed (two of the eleven), so their
 * number per character is a symmetric walk on 0-8 whose steady mix
 * (uniform) the characters start in: the work per frame does not drift
 * with the number of constraints piling up. */
static void random_edit(soak_char* c, const smg_character_state* st,
                        const smg_graph_info* info) {
  float len = 0.0f;
  uint32_t id, op = rnd() % 1200u;
  if (op >= 11) return;
  smg_character_get_path_length(c->ch, &len);
  switch (op) {
    case 0: new_path(c, st); break;
    case 1: append(c); break;
    case 2:
      if (rnd() % 4 == 0) {
        smg_character_clear_path(c->ch);
        c->points = 0;
      }
      break;
    case 3:
      if (len > 0 && c->nid < 8 &&
          smg_character_add_transition(c->ch, uni(0, len),
                                       rnd() % info->style_count,
                                       &id) == SMG_OK)
        c->ids[c->nid++] = id;
      break;
    case 4:
      if (len > 0 && c->nid < 8 &&
          smg_character_add_splice(c->ch, uni(0, len),
                                   rnd() % info->action_count,
                                   &id) == SMG_OK)
        c->ids[c->nid++] = id;
      break;
    case 5:
      if (c->nid) smg_character_move_constraint(c->ch, c->ids[rnd() % c->nid],
                                                uni(0, len));
      break;
    case 6:
    case 10:
      if (c->nid) {
        uint32_t k = rnd() % c->nid;
        smg_character_remove_constraint(c->ch, c->ids[k]);
        c->ids[k] = c->ids[--c->nid];
      }
      break;
    case 7: smg_character_set_style(c->ch, rnd() % info->style_count); break;
    case 8: smg_character_set_action(c->ch, rnd() % info->action_count); break;
    default: smg_character_set_ik(c->ch, rnd() % 4 != 0); break; /* 9 */
  }
}

static int finite_all(const float* v, size_t n) {
  size_t i;
  for (i = 0; i < n; ++i)
    if (!isfinite(v[i])) return 0;
  return 1;
}

typedef struct soak_options {
  uint32_t chars, steps;
  soak_count* count; /* --instructions: counting the windows, else NULL */
  uint32_t window;   /* frames per window (0: a tenth of the steps) */
  double grow; /* test of the growth check: the timed work per frame grows
                  by this share by the end of the run, as a runtime whose
                  steps grow slower would (ballast characters, stepped
                  with the soak's, unchecked: from none at the start to
                  grow x C at the end) */
} soak_options;

/* A new path for a ballast character near the end of its own. */
static void feed_ballast(soak_char* c) {
  smg_character_state st;
  float len = 0.0f;
  memset(&st, 0, sizeof st);
  st.struct_size = sizeof st;
  smg_character_get_state(c->ch, &st);
  smg_character_get_path_length(c->ch, &len);
  if (!(st.flags & SMG_STATE_HAS_PATH) ||
      st.path_distance > len - SOAK_PATH_AHEAD)
    new_path(c, &st);
}

static int soak_graph(const char* path, const soak_options* o,
                      soak_stats* s) {
  const uint32_t chars = o->chars, steps = o->steps;
  const uint32_t ballast = (uint32_t)ceil(o->grow * chars);
  /* With --instructions, SOAK_SETTLE steps (checked like all) before the
   * timed ones: the soak's own start - every character setting off from
   * rest on a new path at once - is more work than the steady random use. */
  const uint32_t settle = o->count ? SOAK_SETTLE : 0;
  const uint32_t window = o->window ? o->window : (steps + 9) / 10;
  static float rot[4 * SOAK_MAX_JOINTS], mats[16 * SOAK_MAX_JOINTS];
  counter gc = {0, 0}, cc = {0, 0};
  smg_graph_desc gd;
  smg_graph* g = NULL;
  smg_graph_info info;
  soak_char* cs;
  size_t size = 0;
  void* blob = read_blob(path, &size);
  long allocs_at_start;
  uint32_t i, f;
  memset(s, 0, sizeof *s);
  if (!blob) {
    fprintf(stderr, "soak: cannot read %s\n", path);
    return 1;
  }
  s->data_speed = data_max_speed(blob, size);
  s->path_bound = SOAK_PATH_START + SOAK_HORIZON * s->data_speed;
  memset(&gd, 0, sizeof gd);
  gd.struct_size = sizeof gd;
  gd.allocator.alloc = count_alloc;
  gd.allocator.free = count_free;
  gd.allocator.user = &gc;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  if (!(s->data_speed > 0.0f) ||
      smg_graph_load_memory(blob, size, &gd, &g) != SMG_OK ||
      smg_graph_get_info(g, &info) != SMG_OK ||
      info.joint_count > SOAK_MAX_JOINTS) {
    fprintf(stderr, "soak: cannot load %s\n", path);
    if (g) smg_graph_destroy(g);
    free(blob);
    return 1;
  }
  cs = (soak_char*)calloc(chars + ballast, sizeof *cs);
  for (i = 0; cs && i < chars + ballast; ++i) {
    smg_character_desc d;
    smg_character_state st;
    memset(&d, 0, sizeof d);
    d.struct_size = sizeof d;
    d.seed = rnd();
    /* the mix of styles and actions the random edits settle into, from
     * the start: the counted windows compare like with like */
    d.initial_style = rnd() % info.style_count;
    d.initial_action = rnd() % info.action_count;
    if (rnd() % 4 == 0) d.flags = SMG_CHARACTER_NO_IK; /* as the edits */
    d.position[0] = 4.0f * (float)(i % 10);
    d.position[2] = 4.0f * (float)(i / 10);
    d.heading = uni(-3.1f, 3.1f);
    d.allocator.alloc = count_alloc;
    d.allocator.free = count_free;
    d.allocator.user = &cc;
    if (smg_character_create(g, &d, &cs[i].ch) != SMG_OK) break;
    memset(&st, 0, sizeof st);
    st.struct_size = sizeof st;
    smg_character_get_state(cs[i].ch, &st);
    smg_character_get_local_pose(cs[i].ch, cs[i].root, rot, info.joint_count);
    new_path(&cs[i], &st);
    add_constraints(&cs[i], rnd() % 9, &info);
  }
  if (!cs || i < chars + ballast) {
    fprintf(stderr, "soak: cannot create %u characters\n", chars + ballast);
    return 1;
  }
  allocs_at_start = gc.allocs + gc.frees + cc.allocs + cc.frees;

  for (f = 0; f < settle + steps; ++f) {
    /* dt jitter around 60 Hz, sometimes 0 or a long hitch */
    uint32_t r = rnd() % 100u;
    float dt = r == 0 ? 0.0f : r == 1 ? 0.1f : uni(0.5f, 1.5f) / 60.0f;
    const uint32_t timed = f < settle ? 0 : f - settle; /* timed steps */
    uint32_t extra = (uint32_t)(o->grow * chars * ((double)timed / steps));
    /* the two windows: the first and the last `window` timed steps */
    const int first = o->count && f >= settle && timed < window;
    const int last = o->count && timed >= steps - window;
    smg_result stepped = SMG_OK;
    if ((first || last) && (timed == 0 || timed == steps - window))
      soak_count_window_begin();
    if (first || last) soak_count_on();
    for (i = 0; i < chars; ++i)
      if (smg_character_step(cs[i].ch, dt) != SMG_OK) stepped = SMG_ERROR_IO;
    for (i = 0; i < extra; ++i) /* --grow */
      if (smg_character_step(cs[chars + i].ch, dt) != SMG_OK)
        stepped = SMG_ERROR_IO;
    if (first || last) soak_count_off();
    if ((first && timed == window - 1 &&
         !soak_count_window_end(o->count, "soak: first window", &s->first)) ||
        (last && timed == steps - 1 &&
         !soak_count_window_end(o->count, "soak: last window", &s->last)))
      return 1;
    for (i = 0; i < extra; ++i) feed_ballast(&cs[chars + i]);
    for (i = 0; i < chars; ++i) {
      soak_char* c = &cs[i];
      smg_character_state st;
      float root[3], dx, dz, speed, len = 0.0f;
      memset(&st, 0, sizeof st);
      st.struct_size = sizeof st;
      if (stepped != SMG_OK || smg_character_get_state(c->ch, &st) != SMG_OK ||
          smg_character_get_local_pose(c->ch, root, rot, info.joint_count) !=
              SMG_OK ||
          smg_character_get_model_matrices(c->ch, SMG_SPACE_WORLD, mats,
                                           info.joint_count) != SMG_OK) {
        fprintf(stderr, "soak: %s: an API call failed\n", path);
        return 1;
      }
      if (!finite_all(root, 3) || !finite_all(rot, 4u * info.joint_count) ||
          !finite_all(mats, 16u * info.joint_count) ||
          !finite_all(st.position, 3) || !isfinite(st.heading) ||
          !isfinite(st.path_error) || !isfinite(st.path_distance) ||
          !isfinite(st.sync_rate))
        s->nonfinite++;
      dx = root[0] - c->root[0];
      dz = root[2] - c->root[2];
      speed = dt > 0.0f ? sqrtf(dx * dx + dz * dz) / dt : 0.0f;
      if (sqrtf(dx * dx + dz * dz) >
          s->data_speed * SOAK_SPEED_MARGIN * dt + SOAK_JUMP_SLACK)
        s->jumps++;
      else if (speed > s->max_speed)
        s->max_speed = speed;
      memcpy(c->root, root, sizeof root);
      smg_character_get_path_length(c->ch, &len);
      if ((st.flags & SMG_STATE_HAS_PATH) &&
          !(st.flags & SMG_STATE_PATH_END_REACHED)) {
        if (st.path_error > s->max_path_error)
          s->max_path_error = st.path_error;
        if (st.path_error > s->path_bound) s->path_errors++;
      }
      /* a character near the end of its path gets a new one, as a game
       * feeds paths ahead (what happens past the end - stopping - is not
       * this check's subject) */
      if ((st.flags & SMG_STATE_PATH_END_REACHED) ||
          !(st.flags & SMG_STATE_HAS_PATH) ||
          st.path_distance > len - SOAK_PATH_AHEAD)
        new_path(c, &st);
      else
        random_edit(c, &st, &info);
      s->frames++;
    }
  }
  s->allocs_after_create =
      gc.allocs + gc.frees + cc.allocs + cc.frees - allocs_at_start;
  for (i = 0; i < chars + ballast; ++i) smg_character_destroy(cs[i].ch);
  smg_graph_destroy(g);
  free(cs);
  free(blob);
  return 0;
}

/* The growth check: within SOAK_FLAT of flat; with --grow, the injected
 * growth must be caught instead. */
#define SOAK_FLAT 0.10

int main(int argc, char** argv) {
  soak_options o = {100, 10000, NULL, 0, 0.0};
  soak_count count = {NULL, 0};
  int argi, bad = 0, graphs = 0;
  long total = 0;
  for (argi = 1; argi < argc; ++argi) {
    soak_stats s;
    double drift, per = 0.0;
    int ok, flat, caught;
    char growth[256];
    if (strcmp(argv[argi], "--characters") == 0 && argi + 1 < argc) {
      o.chars = (uint32_t)strtoul(argv[++argi], NULL, 10);
      continue;
    }
    if (strcmp(argv[argi], "--steps") == 0 && argi + 1 < argc) {
      o.steps = (uint32_t)strtoul(argv[++argi], NULL, 10);
      continue;
    }
    if (strcmp(argv[argi], "--seed") == 0 && argi + 1 < argc) {
      g_rng = (uint32_t)strtoul(argv[++argi], NULL, 10) | 1u;
      continue;
    }
    if (strcmp(argv[argi], "--instructions") == 0 && argi + 1 < argc) {
      count.out = argv[++argi];
      o.count = &count;
      continue;
    }
    if (strcmp(argv[argi], "--window") == 0 && argi + 1 < argc) {
      o.window = (uint32_t)strtoul(argv[++argi], NULL, 10);
      continue;
    }
    if (strcmp(argv[argi], "--grow") == 0 && argi + 1 < argc) {
      o.grow = strtod(argv[++argi], NULL);
      continue;
    }
    if (o.count && !soak_count_available()) {
      fprintf(stderr,
              "soak: --instructions counts with callgrind: run under "
              "valgrind --tool=callgrind --instr-atstart=no "
              "--collect-atstart=no --callgrind-out-file=%s\n",
              count.out);
      return 1;
    }
    if (o.chars == 0 || o.steps < 10 || !(o.grow >= 0.0 && o.grow <= 1.0) ||
        (o.grow > 0.0 && !o.count) || 2u * o.window > o.steps ||
        soak_graph(argv[argi], &o, &s)) {
      fprintf(stderr, "soak: %s: could not run\n", argv[argi]);
      return 1;
    }
    drift = s.first > 0.0 ? s.last / s.first - 1.0 : 0.0;
    flat = fabs(drift) <= SOAK_FLAT;
    caught = drift > SOAK_FLAT; /* an injected growth, seen as one */
    if (o.count) {
      const uint32_t w = o.window ? o.window : (o.steps + 9) / 10;
      per = s.first / ((double)w * o.chars);
    }
    if (!o.count)
      snprintf(growth, sizeof growth, "step work not counted");
    else
      snprintf(growth, sizeof growth,
               "instructions of the steps, first vs last window %.4g vs "
               "%.4g (%.0f per character-step; %+.2f %%, limit %.0f %%)%s",
               s.first, s.last, per, 100.0 * drift, 100.0 * SOAK_FLAT,
               o.grow > 0.0 ? (caught ? ", injected growth caught"
                                      : ", injected growth MISSED")
                            : "");
    ok = s.nonfinite == 0 && s.jumps == 0 && s.path_errors == 0 &&
         s.allocs_after_create == 0 &&
         (!o.count || (o.grow > 0.0 ? caught : flat));
    printf("soak: %s: %ld character-frames (%u characters x %u steps%s): "
           "%ld non-finite, %ld root jumps (fastest %.2f m/s, data %.2f m/s), "
           "path error max %.2f m (bound %.2f m, %ld over), %ld allocator "
           "calls after create, %s: %s\n",
           argv[argi], s.frames, o.chars, o.steps,
           o.count ? " timed after " SOAK_STR(SOAK_SETTLE) " settling" : "",
           s.nonfinite, s.jumps,
           (double)s.max_speed, (double)s.data_speed,
           (double)s.max_path_error, (double)s.path_bound, s.path_errors,
           s.allocs_after_create, growth, ok ? "ok" : "FAILED");
    fflush(stdout);
    bad |= !ok;
    total += s.frames;
    ++graphs;
  }
  if (!graphs) {
    fprintf(stderr,
            "usage: soak [--characters C] [--steps S] [--seed N] "
            "[--instructions OUT [--window W] [--grow G]] GRAPH.smg...\n");
    return 2;
  }
  printf("soak: %ld character-frames on %d graph(s): %s\n", total, graphs,
         bad ? "FAILED" : "ok");
  return bad;
}
