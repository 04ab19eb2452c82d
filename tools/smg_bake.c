/*
 * smg-bake - bake motion-capture clips into a splicing-motion-graph blob.
 *
 *   smg-bake -m MANIFEST -o OUT.smg [options]
 *   smg-bake --lower walk a.bvh --upper punch b.bvh -o OUT.smg [options]
 *   smg-bake --info FILE.smg
 *   smg-bake --analyze FILE [--reference FILE] [--unit M] [--skip-tpose] [-v]
 *
 * The manifest format is docs/manifest.md; the stages are docs/baker.md.
 * Progress goes to stderr (a bar when stderr is a terminal, otherwise one
 * line per stage); a per-stage timing table is printed at the end.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bake_analyze.h"
#include "bake_manifest.h"
#include "bake_options.h"
#include "blob.h"
#include "smg_bake.h"
#include "smg_format.h"
#include "standing.h"
#include "stopping.h"

/* A buffer aligned as the blob reader requires (16 bytes). 64-bit
 * Windows has no posix_memalign, and its malloc already aligns to 16. */
static void* alloc16(size_t size) {
#ifdef _WIN32
  return malloc(size);
#else
  void* p;
  return posix_memalign(&p, 16, size) == 0 ? p : NULL;
#endif
}

/* The defaults quoted come from bake_options.h, the one place they are
 * set. */
static void usage(FILE* fp) {
  fprintf(fp,
      "usage: smg-bake -m MANIFEST -o OUT.smg [options]\n"
      "       smg-bake --lower STYLE FILE [--upper ACTION FILE ...] -o OUT.smg\n"
      "       smg-bake --info FILE.smg\n"
      "       smg-bake --analyze CLIP [--reference CLIP] [--unit M]\n"
      "                [--skip-tpose] [-v]\n"
      "                (foot strikes, stride period, planted-foot speed,\n"
      "                forward/backward/sideways frame ranges for manifest\n"
      "                frames=A-B; --reference retargets as a bake would)\n"
      "\n"
      "input:\n"
      "  -m, --manifest FILE    clip list (docs/manifest.md)\n"
      "  --lower STYLE FILE     add a locomotion clip (repeatable)\n"
      "  --upper ACTION FILE    add an upper-body action clip (repeatable)\n"
      "  --data-dir DIR         folder relative clip paths are read from\n"
      "  --unit M               file units in metres for --lower/--upper\n"
      "                         clips (CMU: 0.056444; default: guess)\n"
      "  --skip-tpose           drop frame 0 of --lower/--upper clips\n"
      "  --target RIG           retarget every clip onto this rig (.bvh,\n"
      "                         .gltf/.glb/.fbx); default: the first clip's\n"
      "                         skeleton\n"
      "  --target-unit M        rig file units in metres (default: guess)\n"
      "options:\n"
      "  -o, --output FILE      blob to write\n"
      "  --frame-rate HZ        working frame rate (default %g or the\n"
      "                         manifest's)\n"
      "  --no-mirror            do not add mirrored clips\n"
      "  --window S             transition window, seconds (default %.3g)\n"
      "  --percentile P         transition candidates kept, percent of local\n"
      "                         minima per style pair (default %g)\n"
      "  --threshold M          absolute transition distance cap, metres\n"
      "  --max-edge S           longest merged edge, seconds (default %g)\n"
      "  --splice-percentile P  splice candidates kept per action (%g)\n"
      "  --splices-per-region N best splices per %g s region (%u)\n"
      "  --threads N            worker threads (default %u, at most %u)\n"
      "  -q, --quiet            no progress output\n"
      "  -h, --help\n",
      (double)SMGB_DEFAULT_FRAME_RATE, (double)SMGB_DEFAULT_WINDOW_SECONDS,
      (double)SMGB_DEFAULT_TRANSITION_PERCENTILE,
      (double)SMGB_DEFAULT_MAX_EDGE_SECONDS,
      (double)SMGB_DEFAULT_SPLICE_PERCENTILE,
      (double)SMGB_DEFAULT_SPLICE_REGION_SECONDS,
      SMGB_DEFAULT_SPLICES_PER_REGION, SMGB_DEFAULT_THREADS,
      SMGB_MAX_THREADS);
}

/* ---- progress ------------------------------------------------------------- */

typedef struct progress_state {
  int tty;
  int quiet;
  const char* last_stage;
  int last_pct;
} progress_state;

static void on_progress(const char* stage, float fraction, void* user) {
  progress_state* p = user;
  if (p->quiet) return;
  if (p->tty) {
    int pct = (int)(fraction * 100.0f + 0.5f), i, fill;
    if (stage == p->last_stage && pct == p->last_pct) return;
    fill = pct * 30 / 100;
    fprintf(stderr, "\r  %-18s [", stage);
    for (i = 0; i < 30; ++i) fputc(i < fill ? '#' : ' ', stderr);
    fprintf(stderr, "] %3d%%", pct);
    if (fraction >= 1.0f) fputc('\n', stderr);
    fflush(stderr);
    p->last_pct = pct;
    p->last_stage = stage;
  } else if (stage != p->last_stage) {
    fprintf(stderr, "smg-bake: %s ...\n", stage);
    p->last_stage = stage;
  }
}

/* ---- --info --------------------------------------------------------------- */

static const char* tag_name(uint32_t tag, char out[5]) {
  out[0] = (char)(tag & 0xff);
  out[1] = (char)((tag >> 8) & 0xff);
  out[2] = (char)((tag >> 16) & 0xff);
  out[3] = (char)((tag >> 24) & 0xff);
  out[4] = '\0';
  return out;
}

static void graph_summary(const char* title, const smgi_graph_data* g,
                          const smgi_node* nodes, uint32_t nn,
                          const smgi_edge* edges, uint32_t ne,
                          uint32_t nodes_before, uint32_t edges_before,
                          const smgi_label* labels, uint32_t label_count) {
  uint32_t e, transitions = 0, changes = 0, frames = 0, l, c;
  uint32_t source = 0, used = 0, role = 0;
  double arc = 0.0, maxlen = 0.0, cost = 0.0;
  for (e = 0; e < ne; ++e) {
    if (edges[e].flags & SMGI_EDGE_TRANSITION) {
      ++transitions;
      cost += edges[e].cost;
    } else {
      used += edges[e].frame_count;
      role = g->clips[g->frames[edges[e].first_frame].clip].flags &
             (SMGI_CLIP_LOWER | SMGI_CLIP_UPPER);
    }
    if (edges[e].flags & SMGI_EDGE_STYLE_CHANGE) ++changes;
    frames += edges[e].frame_count;
    arc += edges[e].arc_length;
    if (edges[e].frame_count > maxlen) maxlen = edges[e].frame_count;
  }
  printf("%s graph: %u nodes, %u edges (before simplification: %u nodes, "
         "%u edges)\n", title, nn, ne, nodes_before, edges_before);
  for (c = 0; c < g->clip_count; ++c)
    if ((g->clips[c].flags & role) && !(g->clips[c].flags & SMGI_CLIP_BLEND))
      source += g->clips[c].frame_count;
  printf("  %u transition edges (mean cost %.3f m), %u label-changing, "
         "%u frames on edges, longest edge %.2f s, total arc %.1f m\n",
         transitions, transitions ? cost / transitions : 0.0, changes, frames,
         maxlen / g->info->frame_rate, arc);
  printf("  original motion on edges: %u of %u clip frames (%.0f %%)\n", used,
         source, source ? 100.0 * used / source : 0.0);
  for (l = 0; l < label_count; ++l) {
    uint32_t n, cnt = 0;
    for (n = 0; n < nn; ++n) cnt += nodes[n].label == l;
    if (cnt) printf("  %-10s %u nodes\n", g->strings + labels[l].name, cnt);
  }
}

/* The standing motion the runtime will find (standing.h): what a
 * character plays at rest. */
static void standing_summary(const smgi_graph_data* g) {
  uint32_t n = smgi_standing_find(g->frames, g->frame_count, g->clips,
                                  g->clip_count, g->info->frame_rate,
                                  g->info->leg_length, NULL, 0);
  smgi_stand* s = n ? malloc(n * sizeof *s) : NULL;
  double t[2] = {0.0, 0.0};
  uint32_t k;
  if (n && !s) return;
  smgi_standing_find(g->frames, g->frame_count, g->clips, g->clip_count,
                     g->info->frame_rate, g->info->leg_length, s, n);
  for (k = 0; k < n; ++k)
    t[(g->clips[s[k].clip].flags & SMGI_CLIP_LOWER) ? 0 : 1] +=
        s[k].count / g->info->frame_rate;
  printf("standing motion: %u stretches, %.1f s in locomotion clips, %.1f s "
         "in action clips%s\n", n, t[0], t[1],
         n ? "" : " (none)");
  free(s);
}

/* The stopping and starting motion the runtime will find (stopping.h):
 * where a graph has it, stops and starts come from the data. */
static void stopping_summary(const smgi_graph_data* g) {
  uint32_t n = smgi_stopping_find(g->frames, g->frame_count, g->clips,
                                  g->clip_count, g->info->frame_rate,
                                  g->info->leg_length, NULL, 0);
  smgi_stop_seg* s = n ? malloc(n * sizeof *s) : NULL;
  uint32_t k, stops = 0;
  if (n && !s) return;
  smgi_stopping_find(g->frames, g->frame_count, g->clips, g->clip_count,
                     g->info->frame_rate, g->info->leg_length, s, n);
  for (k = 0; k < n; ++k) stops += s[k].kind == SMGI_STOP_KIND_STOP;
  printf("stopping motion: %u stops, %u starts%s\n", stops, n - stops,
         n ? "" : " (stops and starts by the foot IK)");
  free(s);
}

static int info(const char* path) {
  FILE* f = fopen(path, "rb");
  long size;
  void* data = NULL;
  smgi_graph_data g;
  char err[512];
  smg_result r;
  const smgi_blob_header* h;
  const smgi_blob_section* secs;
  uint32_t i, a;
  char tn[5];
  if (!f) {
    fprintf(stderr, "smg-bake: %s: cannot open\n", path);
    return 1;
  }
  if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 ||
      fseek(f, 0, SEEK_SET) != 0) {
    fprintf(stderr, "smg-bake: %s: cannot read\n", path);
    fclose(f);
    return 1;
  }
  data = alloc16(size > 0 ? (size_t)size : 16);
  if (!data) {
    fclose(f);
    fprintf(stderr, "smg-bake: out of memory\n");
    return 1;
  }
  if (fread(data, 1, (size_t)size, f) != (size_t)size) {
    fprintf(stderr, "smg-bake: %s: short read\n", path);
    fclose(f);
    free(data);
    return 1;
  }
  fclose(f);
  r = smgi_blob_read(data, (size_t)size, 0, &g, err, sizeof err);
  if (r != SMG_OK) {
    fprintf(stderr, "smg-bake: %s: not a valid graph blob: %s (%s)\n", path,
            err, smg_result_string(r));
    free(data);
    return 1;
  }
  h = data;
  secs = (const smgi_blob_section*)((const char*)data + h->header_size);
  printf("%s: graph blob version %u, %ld bytes, %.1f Hz, window %.3f s\n",
         path, h->version, size, g.info->frame_rate,
         g.info->window_seconds);
  printf("skeleton: %u joints, pelvis %s, spine base %s, leg length %.3f m\n",
         g.joint_count, g.strings + g.joints[g.info->pelvis_joint].name,
         g.strings + g.joints[g.info->spine_base_joint].name,
         g.info->leg_length);
  for (i = 0; i < g.joint_count; ++i) {
    static const char* parts[] = {"root", "lower", "upper"};
    const smgi_joint* j = &g.joints[i];
    printf("  %2u %-16s parent %3d  %-5s mirror %-16s mass %.3f  bone "
           "%.3f m\n", i, g.strings + j->name, (int)j->parent,
           j->body_part < 3 ? parts[j->body_part] : "?",
           g.strings + g.joints[j->mirror].name, j->mass_ratio,
           sqrt((double)j->offset[0] * j->offset[0] +
                (double)j->offset[1] * j->offset[1] +
                (double)j->offset[2] * j->offset[2]));
  }
  printf("styles:");
  for (i = 0; i < g.style_count; ++i)
    printf(" %s", g.strings + g.styles[i].name);
  printf("\nactions:");
  for (i = 0; i < g.action_count; ++i)
    printf(" %s", g.strings + g.actions[i].name);
  printf("\nclips: %u (%u frames in the pool)\n", g.clip_count,
         g.frame_count);
  for (i = 0; i < g.clip_count; ++i) {
    const smgi_clip* c = &g.clips[i];
    uint32_t is_lower = (c->flags & SMGI_CLIP_LOWER) != 0;
    const smgi_label* lab = is_lower ? g.styles : g.actions;
    uint32_t lc = is_lower ? g.style_count : g.action_count;
    /* how much of the clip the pruned graph still plays */
    const smgi_edge* edges = is_lower ? g.lower_edges : g.upper_edges;
    uint32_t ne = is_lower ? g.lower_edge_count : g.upper_edge_count, e;
    uint32_t used = 0;
    for (e = 0; e < ne; ++e)
      if (edges[e].first_frame >= c->first_frame &&
          edges[e].first_frame < c->first_frame + c->frame_count)
        used += edges[e].frame_count;
    printf("  %2u %-28s %5u frames (%6.2f s) %3.0f%% on edges %-5s %-8s%s%s\n",
           i, g.strings + c->name, c->frame_count,
           c->frame_count / g.info->frame_rate,
           c->frame_count ? 100.0 * used / c->frame_count : 0.0,
           is_lower ? "lower" : "upper",
           (c->flags & SMGI_CLIP_BLEND) ? "-"
           : c->label < lc             ? g.strings + lab[c->label].name
                                       : "?",
           (c->flags & SMGI_CLIP_MIRROR) ? " mirrored" : "",
           (c->flags & SMGI_CLIP_BLEND) ? " blended transitions" : "");
  }
  graph_summary("lower", &g, g.lower_nodes, g.lower_node_count, g.lower_edges,
                g.lower_edge_count, g.info->lower_nodes_before_simplify,
                g.info->lower_edges_before_simplify, g.styles, g.style_count);
  graph_summary("upper", &g, g.upper_nodes, g.upper_node_count, g.upper_edges,
                g.upper_edge_count, g.info->upper_nodes_before_simplify,
                g.info->upper_edges_before_simplify, g.actions,
                g.action_count);
  printf("splice candidates: %u\n", g.splice_count);
  for (a = 0; a < g.action_count; ++a) {
    uint32_t cnt = 0;
    double best = INFINITY, sum = 0.0;
    for (i = 0; i < g.splice_count; ++i)
      if (g.splices[i].action == a) {
        ++cnt;
        sum += g.splices[i].distance;
        if (g.splices[i].distance < best) best = g.splices[i].distance;
      }
    if (cnt)
      printf("  %-10s %u candidates, distance best %.3f m, mean %.3f m\n",
             g.strings + g.actions[a].name, cnt, best, sum / cnt);
  }
  standing_summary(&g);
  stopping_summary(&g);
  printf("sections:\n");
  for (i = 0; i < h->section_count; ++i)
    printf("  %s %9llu bytes  %7u records\n", tag_name(secs[i].tag, tn),
           (unsigned long long)secs[i].size, secs[i].count);
  free(data);
  return 0;
}

/* ---- main ----------------------------------------------------------------- */

static int parse_float(const char* opt, const char* s, float* out) {
  char* end;
  double v = strtod(s, &end);
  if (end == s || *end || !isfinite(v)) {
    fprintf(stderr, "smg-bake: %s: '%s' is not a number\n", opt, s);
    return 0;
  }
  *out = (float)v;
  return 1;
}

static int parse_u32(const char* opt, const char* s, uint32_t* out) {
  char* end;
  long v = strtol(s, &end, 10);
  if (end == s || *end || v < 0 || v > 1000000) {
    fprintf(stderr, "smg-bake: %s: '%s' is not a count\n", opt, s);
    return 0;
  }
  *out = (uint32_t)v;
  return 1;
}

/* Every problem of the bake, one line each (warnings too, even with -q),
 * then how many errors there were when more than one. */
static void print_problems(const char* manifest, const smg_bake_result* res) {
  const char* line = res->problems;
  while (*line) {
    const char* end = strchr(line, '\n');
    int n = end ? (int)(end - line) : (int)strlen(line);
    fprintf(stderr, "smg-bake: %s%s%.*s\n", manifest ? manifest : "",
            manifest ? ": " : "", n, line);
    line += n + (end ? 1 : 0);
  }
  if (!res->problems[0] && res->error[0])
    fprintf(stderr, "smg-bake: %s%s%s\n", manifest ? manifest : "",
            manifest ? ": " : "", res->error);
  if (res->error_count > 1)
    fprintf(stderr, "smg-bake: %u errors\n", res->error_count);
}

int main(int argc, char** argv) {
  const char *manifest = NULL, *output = NULL, *data_dir = NULL;
  smgb_manifest m;
  smgb_error err;
  smg_bake_desc desc;
  smg_bake_result res;
  smg_bake_clip_desc* descs = NULL;
  progress_state ps;
  float unit = 0.0f, frame_rate = 0.0f;
  uint32_t skip = 0, i;
  int have_m = 0, code = 1;
  smg_result r;
  struct extra {
    uint32_t role;
    const char* label;
    const char* file;
  } extra[256];
  uint32_t nextra = 0;
  const char *analyze = NULL, *reference = NULL, *target = NULL;
  float target_unit = 0.0f;
  int verbose = 0;

  memset(&desc, 0, sizeof desc);
  memset(&ps, 0, sizeof ps);
  desc.struct_size = sizeof desc;
  desc.options.struct_size = sizeof desc.options;
  for (i = 1; i < (uint32_t)argc; ++i) {
    const char* a = argv[i];
    const char* v = i + 1 < (uint32_t)argc ? argv[i + 1] : NULL;
#define NEED(n)                                                         \
  if (i + (n) >= (uint32_t)argc) {                                      \
    fprintf(stderr, "smg-bake: %s needs %d argument(s)\n", a, (n));     \
    return 2;                                                           \
  }
    if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
      usage(stdout);
      return 0;
    } else if (!strcmp(a, "--info")) {
      NEED(1);
      return info(v);
    } else if (!strcmp(a, "--analyze")) {
      NEED(1); analyze = v; ++i;
    } else if (!strcmp(a, "--reference")) {
      NEED(1); reference = v; ++i;
    } else if (!strcmp(a, "-v") || !strcmp(a, "--verbose")) {
      verbose = 1;
    } else if (!strcmp(a, "-m") || !strcmp(a, "--manifest")) {
      NEED(1); manifest = v; ++i;
    } else if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
      NEED(1); output = v; ++i;
    } else if (!strcmp(a, "--data-dir")) {
      NEED(1); data_dir = v; ++i;
    } else if (!strcmp(a, "--lower") || !strcmp(a, "--upper")) {
      NEED(2);
      if (nextra == sizeof extra / sizeof extra[0]) {
        fprintf(stderr, "smg-bake: too many clips on the command line\n");
        return 2;
      }
      extra[nextra].role = a[2] == 'l' ? SMG_BAKE_ROLE_LOWER
                                       : SMG_BAKE_ROLE_UPPER;
      extra[nextra].label = argv[i + 1];
      extra[nextra].file = argv[i + 2];
      ++nextra;
      i += 2;
    } else if (!strcmp(a, "--unit")) {
      NEED(1); if (!parse_float(a, v, &unit)) return 2; ++i;
    } else if (!strcmp(a, "--target")) {
      NEED(1); target = v; ++i;
    } else if (!strcmp(a, "--target-unit")) {
      NEED(1); if (!parse_float(a, v, &target_unit)) return 2; ++i;
    } else if (!strcmp(a, "--skip-tpose")) {
      skip = 1;
    } else if (!strcmp(a, "--frame-rate")) {
      NEED(1); if (!parse_float(a, v, &frame_rate)) return 2; ++i;
    } else if (!strcmp(a, "--no-mirror")) {
      desc.options.no_mirror = 1;
    } else if (!strcmp(a, "--window")) {
      NEED(1);
      if (!parse_float(a, v, &desc.options.window_seconds)) return 2;
      ++i;
    } else if (!strcmp(a, "--percentile")) {
      NEED(1);
      if (!parse_float(a, v, &desc.options.transition_percentile)) return 2;
      ++i;
    } else if (!strcmp(a, "--threshold")) {
      NEED(1);
      if (!parse_float(a, v, &desc.options.transition_threshold)) return 2;
      ++i;
    } else if (!strcmp(a, "--max-edge")) {
      NEED(1);
      if (!parse_float(a, v, &desc.options.max_edge_seconds)) return 2;
      ++i;
    } else if (!strcmp(a, "--splice-percentile")) {
      NEED(1);
      if (!parse_float(a, v, &desc.options.splice_percentile)) return 2;
      ++i;
    } else if (!strcmp(a, "--splices-per-region")) {
      NEED(1);
      if (!parse_u32(a, v, &desc.options.splices_per_region)) return 2;
      ++i;
    } else if (!strcmp(a, "--threads")) {
      NEED(1); if (!parse_u32(a, v, &desc.options.threads)) return 2; ++i;
    } else if (!strcmp(a, "-q") || !strcmp(a, "--quiet")) {
      ps.quiet = 1;
    } else {
      fprintf(stderr, "smg-bake: unknown option '%s' (try --help)\n", a);
      return 2;
    }
#undef NEED
  }
  if (analyze) {
    err.message[0] = '\0';
    r = smgb_analyze_file(analyze, reference, unit, skip, frame_rate, verbose,
                          stdout, &err);
    if (r != SMG_OK)
      fprintf(stderr, "smg-bake: %s\n", err.message[0] ? err.message
                                                       : smg_result_string(r));
    return r == SMG_OK ? 0 : 1;
  }
  if ((!manifest && nextra == 0) || !output) {
    usage(stderr);
    return 2;
  }
  err.message[0] = '\0';
  if (manifest) {
    r = smgb_manifest_load(manifest, data_dir, &m, &err);
    if (r != SMG_OK) {
      fprintf(stderr, "smg-bake: %s\n", err.message[0] ? err.message
                                                       : smg_result_string(r));
      return 1;
    }
  } else {
    r = smgb_manifest_init(&m, data_dir);
    if (r != SMG_OK) {
      fprintf(stderr, "smg-bake: %s\n", smg_result_string(r));
      return 1;
    }
  }
  have_m = 1;
  for (i = 0; i < nextra; ++i) {
    smgb_manifest_clip c;
    memset(&c, 0, sizeof c);
    c.role = extra[i].role;
    snprintf(c.label, sizeof c.label, "%s", extra[i].label);
    c.unit_scale = unit;
    c.skip_first_frame = skip;
    c.mirror = SMG_BAKE_MIRROR_DEFAULT;
    r = smgb_manifest_add(&m, &c, extra[i].file, 1, &err);
    if (r != SMG_OK) {
      fprintf(stderr, "smg-bake: %s\n", err.message[0] ? err.message
                                                       : smg_result_string(r));
      goto out;
    }
  }
  descs = calloc(m.clip_count ? m.clip_count : 1, sizeof *descs);
  if (!descs) {
    fprintf(stderr, "smg-bake: out of memory\n");
    goto out;
  }
  if ((r = smgb_manifest_descs(&m, descs, m.clip_count)) != SMG_OK) {
    fprintf(stderr, "smg-bake: %s\n", smg_result_string(r));
    goto out;
  }
  desc.clips = descs;
  desc.clip_count = m.clip_count;
  desc.options.frame_rate = frame_rate > 0.0f ? frame_rate : m.frame_rate;
  /* --target overrides the manifest's `target` */
  desc.target_path = target ? target : m.target[0] ? m.target : NULL;
  desc.target_unit_scale = target ? target_unit : m.target_unit;
  desc.target_animation = target ? 0 : m.target_animation;
  ps.tty = isatty(2);
  ps.last_pct = -1;
  desc.progress = on_progress;
  desc.progress_user = &ps;
  memset(&res, 0, sizeof res);
  res.struct_size = sizeof res;
  r = smg_bake_run(&desc, &res);
  if (ps.tty && !ps.quiet && (r != SMG_OK || res.warning_count))
    fputc('\n', stderr);
  print_problems(manifest, &res);
  if (r != SMG_OK) goto out;
  {
    char werr[512];
    if (smg_bake_write_file(&res, output, werr, sizeof werr) != SMG_OK) {
      fprintf(stderr, "smg-bake: %s\n", werr);
      smg_bake_result_free(&res);
      goto out;
    }
  }
  if (!ps.quiet) {
    const smg_bake_stats* s = &res.stats;
    fprintf(stderr, "\n  %-22s %10s %10s %10s\n", "stage", "seconds",
            "cpu s", "peak MB");
    for (i = 0; i < res.stage_count; ++i)
      fprintf(stderr, "  %-22s %10.3f %10.3f %10.1f\n", res.stages[i].name,
              res.stages[i].seconds, res.stage_cpu_seconds[i],
              (double)res.stage_peak_bytes[i] / 1048576.0);
    fprintf(stderr, "  %-22s %10.3f %10.3f %10.1f\n", "total",
            res.total_seconds, res.total_cpu_seconds,
            (double)res.peak_bytes / 1048576.0);
    if (res.skipped_clip_count)
      fprintf(stderr, "\n  %u unusable clips skipped (named above)\n",
              res.skipped_clip_count);
    if (res.covered_clip_count)
      fprintf(stderr,
              "\n  covered %u clips (%u frames): left out, kept clips of "
              "their labels already hold their motion\n",
              res.covered_clip_count, res.covered_frame_count);
    fprintf(stderr,
            "\n  clips %u, frames %u + %u blended\n"
            "  lower graph: %u nodes / %u edges before simplification, "
            "%u / %u after (%u transition candidates)\n"
            "  upper graph: %u nodes / %u edges before simplification, "
            "%u / %u after (%u transition candidates)\n"
            "  splice candidates: %u, coverage %.1f %% of locomotion frames "
            "within 1 s for every action (longest wait %.2f s)\n"
            "  wrote %s (%zu bytes)\n",
            s->clip_count, s->source_frames, s->blend_frames,
            s->lower_nodes_before, s->lower_edges_before, s->lower_nodes,
            s->lower_edges, s->lower_candidates, s->upper_nodes_before,
            s->upper_edges_before, s->upper_nodes, s->upper_edges,
            s->upper_candidates, s->splice_count,
            100.0 * s->splice_coverage, s->splice_max_gap, output,
            res.blob_size);
  }
  smg_bake_result_free(&res);
  code = 0;
out:
  free(descs);
  if (have_m) smgb_manifest_free(&m);
  return code;
}
