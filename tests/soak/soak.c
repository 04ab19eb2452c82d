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
 *   - with --timing: the step time is flat: per frame, the CPU time of
 *     stepping all characters once is measured, and so is a fixed,
 *     memory-bound reference workload right after it; the ratio of their medians over
 *     the last 10 % of the run is within 10 % of the same ratio over the
 *     first 10 %. Thread CPU time leaves out time other processes take;
 *     the in-run reference cancels what they still change (clock
 *     frequency, shared caches) - it slows down with the machine, a
 *     runtime that degrades over time does not; medians ignore the few
 *     frames that replan or get preempted.
 * Prints one summary line per graph and one in total; exit status 1 on
 * any failed check.
 *
 *   soak [--characters C] [--steps S] [--seed N] [--timing] GRAPH.smg...
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "blob.h"
#include "quat_pack.h"
#include "smg.h"

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
  double first_ratio, last_ratio; /* step time / reference, medians */
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

/* One random edit now and then: ten kinds, each one in 1200 frames, so
 * about one edit every 2 s per character at 60 Hz. */
static void random_edit(soak_char* c, const smg_character_state* st,
                        const smg_graph_info* info) {
  float len = 0.0f;
  uint32_t id, op = rnd() % 1200u;
  if (op >= 10) return;
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
      if (c->nid) {
        uint32_t k = rnd() % c->nid;
        smg_character_remove_constraint(c->ch, c->ids[k]);
        c->ids[k] = c->ids[--c->nid];
      }
      break;
    case 7: smg_character_set_style(c->ch, rnd() % info->style_count); break;
    case 8: smg_character_set_action(c->ch, rnd() % info->action_count); break;
    default: smg_character_set_ik(c->ch, rnd() % 4 != 0); break;
  }
}

static int finite_all(const float* v, size_t n) {
  size_t i;
  for (i = 0; i < n; ++i)
    if (!isfinite(v[i])) return 0;
  return 1;
}

static double thread_cpu_seconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The fixed reference workload timed beside every frame: like the
 * runtime, it reads memory spread over a few MiB (a graph and a hundred
 * characters' state) and does some float math per read, so it feels the
 * same cache and memory pressure from other processes as the steps do:
 * 4096 dependent reads through a random cycle over 4 MiB. */
#define SOAK_REF_WORDS (1u << 20)
static uint32_t* g_ref_next;
static volatile float g_sink;
static int reference_init(void) {
  uint32_t i;
  g_ref_next = (uint32_t*)malloc(sizeof(uint32_t) * SOAK_REF_WORDS);
  if (!g_ref_next) return 0;
  for (i = 0; i < SOAK_REF_WORDS; ++i) g_ref_next[i] = i;
  for (i = SOAK_REF_WORDS - 1; i > 0; --i) { /* Sattolo: one cycle */
    uint32_t j = rnd() % i, t = g_ref_next[i];
    g_ref_next[i] = g_ref_next[j];
    g_ref_next[j] = t;
  }
  return 1;
}
static double reference_work(void) {
  double c0 = thread_cpu_seconds();
  float acc = 0.0f;
  uint32_t i, at = 0;
  for (i = 0; i < 4096; ++i) {
    at = g_ref_next[at];
    acc += sqrtf((float)at + acc * 1e-6f);
  }
  g_sink = acc;
  return thread_cpu_seconds() - c0;
}

static int cmp_double(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y;
}

static double median(double* v, size_t n) {
  qsort(v, n, sizeof *v, cmp_double);
  return n ? (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2])) : 0.0;
}

static int soak_graph(const char* path, uint32_t chars, uint32_t steps,
                      soak_stats* s) {
  static float rot[4 * SOAK_MAX_JOINTS], mats[16 * SOAK_MAX_JOINTS];
  counter gc = {0, 0}, cc = {0, 0};
  smg_graph_desc gd;
  smg_graph* g = NULL;
  smg_graph_info info;
  soak_char* cs;
  double *step_cpu, *ref_cpu;
  size_t size = 0;
  void* blob = read_blob(path, &size);
  long allocs_at_start;
  uint32_t i, f, tenth;
  memset(s, 0, sizeof *s);
  if (!blob || (!g_ref_next && !reference_init())) {
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
  cs = (soak_char*)calloc(chars, sizeof *cs);
  step_cpu = (double*)malloc(sizeof(double) * steps);
  ref_cpu = (double*)malloc(sizeof(double) * steps);
  for (i = 0; cs && i < chars; ++i) {
    smg_character_desc d;
    smg_character_state st;
    memset(&d, 0, sizeof d);
    d.struct_size = sizeof d;
    d.seed = rnd();
    /* the mix of styles and actions the random edits settle into, from
     * the start: the timing windows compare like with like */
    d.initial_style = rnd() % info.style_count;
    d.initial_action = rnd() % info.action_count;
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
  }
  if (!cs || !step_cpu || !ref_cpu || i < chars) {
    fprintf(stderr, "soak: cannot create %u characters\n", chars);
    return 1;
  }
  allocs_at_start = gc.allocs + gc.frees + cc.allocs + cc.frees;

  for (f = 0; f < steps; ++f) {
    /* dt jitter around 60 Hz, sometimes 0 or a long hitch */
    uint32_t r = rnd() % 100u;
    float dt = r == 0 ? 0.0f : r == 1 ? 0.1f : uni(0.5f, 1.5f) / 60.0f;
    double c0 = thread_cpu_seconds();
    smg_result stepped = SMG_OK;
    for (i = 0; i < chars; ++i)
      if (smg_character_step(cs[i].ch, dt) != SMG_OK) stepped = SMG_ERROR_IO;
    step_cpu[f] = thread_cpu_seconds() - c0;
    ref_cpu[f] = reference_work();
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
  tenth = steps / 10 ? steps / 10 : 1;
  s->first_ratio = median(step_cpu, tenth) / median(ref_cpu, tenth);
  s->last_ratio = median(step_cpu + steps - tenth, tenth) /
                  median(ref_cpu + steps - tenth, tenth);
  for (i = 0; i < chars; ++i) smg_character_destroy(cs[i].ch);
  smg_graph_destroy(g);
  free(cs);
  free(step_cpu);
  free(ref_cpu);
  free(blob);
  return 0;
}

int main(int argc, char** argv) {
  uint32_t chars = 100, steps = 10000;
  int timing = 0, argi, bad = 0, graphs = 0;
  long total = 0;
  for (argi = 1; argi < argc; ++argi) {
    soak_stats s;
    double drift;
    int ok;
    if (strcmp(argv[argi], "--characters") == 0 && argi + 1 < argc) {
      chars = (uint32_t)strtoul(argv[++argi], NULL, 10);
      continue;
    }
    if (strcmp(argv[argi], "--steps") == 0 && argi + 1 < argc) {
      steps = (uint32_t)strtoul(argv[++argi], NULL, 10);
      continue;
    }
    if (strcmp(argv[argi], "--seed") == 0 && argi + 1 < argc) {
      g_rng = (uint32_t)strtoul(argv[++argi], NULL, 10) | 1u;
      continue;
    }
    if (strcmp(argv[argi], "--timing") == 0) {
      timing = 1;
      continue;
    }
    if (chars == 0 || steps < 10 || soak_graph(argv[argi], chars, steps, &s)) {
      fprintf(stderr, "soak: %s: could not run\n", argv[argi]);
      return 1;
    }
    drift = s.first_ratio > 0.0 ? s.last_ratio / s.first_ratio - 1.0 : 0.0;
    ok = s.nonfinite == 0 && s.jumps == 0 && s.path_errors == 0 &&
         s.allocs_after_create == 0 && (!timing || fabs(drift) <= 0.10);
    printf("soak: %s: %ld character-frames (%u characters x %u steps): "
           "%ld non-finite, %ld root jumps (fastest %.2f m/s, data %.2f m/s), "
           "path error max %.2f m (bound %.2f m, %ld over), %ld allocator "
           "calls after create, step time / reference first vs last 10 %% "
           "%.3f vs %.3f (%+.1f %%%s): %s\n",
           argv[argi], s.frames, chars, steps, s.nonfinite, s.jumps,
           (double)s.max_speed, (double)s.data_speed,
           (double)s.max_path_error, (double)s.path_bound, s.path_errors,
           s.allocs_after_create, s.first_ratio, s.last_ratio, 100.0 * drift,
           timing ? "" : ", not checked", ok ? "ok" : "FAILED");
    bad |= !ok;
    total += s.frames;
    ++graphs;
  }
  if (!graphs) {
    fprintf(stderr,
            "usage: soak [--characters C] [--steps S] [--seed N] [--timing] "
            "GRAPH.smg...\n");
    return 2;
  }
  printf("soak: %ld character-frames on %d graph(s): %s\n", total, graphs,
         bad ? "FAILED" : "ok");
  free(g_ref_next);
  return bad;
}
