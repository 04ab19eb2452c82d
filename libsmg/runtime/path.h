/*
 * path.h - the polyline a character follows (path.c): interleaved (x, z)
 * points with cumulative arc lengths, evaluated by arc length and
 * projected onto in O(1) amortized from a segment hint. The buffers are
 * carved out of the character's block at create (character.c).
 */
#ifndef SMG_PATH_H
#define SMG_PATH_H

#include <stdint.h>

typedef struct smgi_path {
  float* xz;       /* 2 * capacity */
  float* cum;      /* capacity: arc length at each point */
  uint32_t count, capacity;
  float length;
} smgi_path;

void smgi_path_reset(smgi_path* p);
/* The segment arc length s (clamped to [0, length]) lies on: the last i
 * with cum[i] <= s, walked to from segment `hint`; 0 for a path of fewer
 * than two points. */
uint32_t smgi_path_find(const smgi_path* p, float s, uint32_t hint);
/* The heading smgi_path_eval reports on segment `seg` (an atan2: callers
 * that evaluate several points on one segment ask once). */
float smgi_path_heading(const smgi_path* p, uint32_t seg);

/* smgi_path_find, answered inline when s lies on the hint's own segment:
 * queries move a little at a time (steering, planning, rest), so most do. */
static inline uint32_t smgi_path_segment(const smgi_path* p, float s,
                                         uint32_t hint) {
  if (hint + 1u < p->count && s >= p->cum[hint] && s <= p->cum[hint + 1u] &&
      s <= p->length)
    return hint;
  return smgi_path_find(p, s, hint);
}

/* Point and tangent heading at arc length s (clamped); *seg is a hint in
 * and the segment out. */
void smgi_path_eval(const smgi_path* p, float s, uint32_t* seg, float* x,
                    float* z, float* heading);
/* Nearest point search starting at segment *seg, walking while the
 * distance shrinks (bounded steps). Returns arc length, writes *seg and the
 * distance. */
float smgi_path_project_local(const smgi_path* p, float x, float z,
                              uint32_t* seg, float* out_dist);
/* smgi_path_project_local, and when that leaves (x, z) more than `off`
 * from the path, a later pass within `ahead` metres of arc that is
 * nearer by SMGI_PATH_PROJECT_TIE wins (a cut across a hairpin's tip
 * joins the leg beyond it; the local walk cannot climb over the tip). */
float smgi_path_project_ahead(const smgi_path* p, float x, float z,
                              uint32_t* seg, float* out_dist, float off,
                              float ahead);
/* Copy `count` points to index `from`, extend the arc lengths and, if
 * `project`, return the exact nearest point to (px, pz) on the whole path
 * (arc length; *seg, *out_dist set) in the same pass. */
float smgi_path_load(smgi_path* p, const float* xz, uint32_t from,
                     uint32_t count, int project, float px, float pz,
                     uint32_t* seg, float* out_dist);
/* Global nearest point (O(n)). */
float smgi_path_project_global(const smgi_path* p, float x, float z,
                               uint32_t* seg, float* out_dist);
/* All n floats finite with magnitude below SMG_MAX_COORDINATE. */
int smgi_coords_ok(const float* v, uint32_t n);

#endif /* SMG_PATH_H */
