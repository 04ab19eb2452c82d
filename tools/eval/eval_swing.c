/*
 * eval_swing.c - the swing-clearance figure of section 2b: the left toe's
 * height over time on the CMU graph's S-curve, foot IK on with swing
 * clearance (the default) and with SMG_CHARACTER_NO_SWING_CLEARANCE, with
 * the planted-toe band of eval_feet_geom.h drawn in. Shows where the lift
 * acts (fast mid-swing toes that dip into the band) and that standing,
 * landing and push-off are the same curve.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "eval_ctx.h"
#include "eval_feet_geom.h"
#include "eval_joints.h"
#include "svg_plot.h"

#define SWING_RATE 30.0    /* steps per second, as section 2c */
#define SWING_SECONDS 8.0  /* of walking shown */
#define SWING_MAX_POINTS 256

/* Left toe positions (x, y, z per frame, metres) of one run along `xz`;
 * 0 on failure. */
static int toe_positions(smg_graph* g, const eval_joints* j, const float* xz,
                         uint32_t n, uint32_t flags, double* y,
                         size_t frames) {
  smg_character_desc d;
  smg_character* ch = NULL;
  smg_graph_info info;
  float* m = NULL;
  size_t i;
  int ok = 0;
  memset(&info, 0, sizeof(info));
  info.struct_size = sizeof(info);
  memset(&d, 0, sizeof(d));
  d.struct_size = sizeof(d);
  d.flags = flags;
  d.path_capacity = n;
  d.position[0] = xz[0];
  d.position[2] = xz[1];
  d.heading = (float)atan2(xz[2] - xz[0], xz[3] - xz[1]);
  if (smg_graph_get_info(g, &info) != SMG_OK ||
      smg_character_create(g, &d, &ch) != SMG_OK)
    return 0;
  m = (float*)malloc(16 * (size_t)info.joint_count * sizeof(float));
  if (m && smg_character_set_path(ch, xz, n) == SMG_OK) {
    ok = 1;
    for (i = 0; i < frames && ok; ++i) {
      ok = (i == 0 ||
            smg_character_step(ch, (float)(1.0 / SWING_RATE)) == SMG_OK) &&
           smg_character_get_model_matrices(ch, SMG_SPACE_WORLD, m,
                                            info.joint_count) == SMG_OK;
      y[3 * i] = m[16 * j->ltoe + 12];
      y[3 * i + 1] = m[16 * j->ltoe + 13];
      y[3 * i + 2] = m[16 * j->ltoe + 14];
    }
  }
  free(m);
  smg_character_destroy(ch);
  return ok;
}

void eval_figure_swing(eval_ctx* ctx, const void* blob, size_t size) {
  static double path[2 * SWING_MAX_POINTS];
  static float xz[2 * SWING_MAX_POINTS];
  const size_t frames = (size_t)(SWING_SECONDS * SWING_RATE);
  smg_graph* g = NULL;
  eval_joints j;
  svp_figure* fig = NULL;
  double *t = NULL, *on = NULL, *off = NULL, *pos[2] = {NULL, NULL};
  double band[2], edge[2];
  char file[1200];
  size_t n = 0, i;
  FILE* f;
  char line[128];
  if (!ctx->img_dir) return;
  f = fopen("data/paths/s-curve.txt", "r");
  if (!f) return;
  while (n < SWING_MAX_POINTS && fgets(line, sizeof(line), f))
    if (line[0] != '#' &&
        sscanf(line, "%lf %lf", &path[2 * n], &path[2 * n + 1]) == 2)
      ++n;
  fclose(f);
  for (i = 0; i < 2 * n; ++i) xz[i] = (float)path[i];
  t = (double*)malloc(frames * sizeof(double));
  on = (double*)malloc(frames * sizeof(double));
  off = (double*)malloc(frames * sizeof(double));
  pos[0] = (double*)malloc(3 * frames * sizeof(double));
  pos[1] = (double*)malloc(3 * frames * sizeof(double));
  if (n < 2 || !t || !on || !off || !pos[0] || !pos[1] ||
      smg_graph_load_memory(blob, size, NULL, &g) != SMG_OK ||
      !eval_find_joints(g, &j) ||
      !toe_positions(g, &j, xz, (uint32_t)n, 0u, pos[0], frames) ||
      !toe_positions(g, &j, xz, (uint32_t)n, SMG_CHARACTER_NO_SWING_CLEARANCE,
                   pos[1], frames))
    goto done;
  {
    /* heights above the toe's floor level as the planted-toe measure
     * takes it (the run without clearance: its floor is the data's) */
    const double level = eval_feet_floor_level(pos[1], 3, frames);
    for (i = 0; i < frames; ++i) {
      t[i] = (double)i / SWING_RATE;
      on[i] = 100.0 * (pos[0][3 * i + 1] - level);
      off[i] = 100.0 * (pos[1][3 * i + 1] - level);
    }
  }
  fig = svp_create(760, 300,
                   "Left toe height, CMU graph, S-curve: swing clearance "
                   "on (default) and off");
  if (!fig) goto done;
  svp_set_labels(fig, "time (s)", "toe above its floor level (cm)");
  band[0] = band[1] = 100.0 * EVAL_FEET_PLANT_BAND_M;
  edge[0] = 0.0;
  edge[1] = SWING_SECONDS;
  svp_line(fig, edge, band, 2, "#bbbbbb", 1.0, 1,
           "planted band of the measure (2.5 cm)");
  svp_line(fig, t, off, frames, "#999999", 1.5, 1, "swing clearance off");
  svp_line(fig, t, on, frames, "#1f5fd6", 1.5, 0, "swing clearance on");
  eval_img_path(ctx, "eval-swing-clearance.svg", file, sizeof(file));
  if (svp_write(fig, file) != 0) {
    eval_log("cannot write %s", file);
    goto done;
  }
  eval_md(ctx,
          "\nSwing clearance (docs/runtime.md, Foot clean-up): the left "
          "toe over 8 s of the CMU graph's S-curve of section 2c, with "
          "the default clearance and without it. Mid-swing the data's toe "
          "dips back towards the floor while it moves fastest; the lift "
          "keeps it above the clearance there and leaves stance, landing "
          "and push-off alone.\n\n"
          "![left toe height, swing clearance on and off]"
          "(%s/eval-swing-clearance.svg)\n",
          ctx->img_rel);
done:
  svp_destroy(fig);
  if (g) smg_graph_destroy(g);
  free(t);
  free(on);
  free(off);
  free(pos[0]);
  free(pos[1]);
}
