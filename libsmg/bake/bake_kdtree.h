/*
 * bake_kdtree.h - a static kd-tree over window feature vectors
 * (bake_kdtree.c), shared by the pair search (nearest windows,
 * bake_pair_search.c) and the coverage pass (is any window near,
 * bake_coverage.c).
 *
 * Median splits on the dimension of largest spread, leaves of at most
 * SMGB_KD_LEAF windows; ties in the split order are broken by window
 * index, so the tree depends only on its input.
 */
#ifndef BAKE_KDTREE_H
#define BAKE_KDTREE_H

#include <stdint.h>

#define SMGB_KD_LEAF 8u

typedef struct smgb_kd_node {
  uint32_t lo, hi;             /* range of idx[] (leaf) */
  uint32_t left, right;        /* children, 0 = leaf */
  uint32_t dim;
  float split;
} smgb_kd_node;

typedef struct smgb_kd_tree {
  smgb_kd_node* nodes;
  uint32_t count, cap;
  uint32_t* idx;               /* windows of the tree (owned) */
  uint32_t n;
} smgb_kd_tree;

/* Builds the tree over t->idx[0 .. t->n) (filled by the caller) whose
 * features are feat[w * dims .. + dims). Returns 0 when out of memory. */
int smgb_kd_build(smgb_kd_tree* t, const float* feat, uint32_t dims);

/* 1 when feature vector f lies within squared distance r2 of q; the sum
 * stops as soon as it passes r2 (most candidates are far). */
static inline int smgb_kd_within(const float* f, const float* q,
                                 uint32_t dims, float r2) {
  float acc = 0.0f;
  uint32_t a;
  for (a = 0; a < dims && acc <= r2; ++a) {
    float df = f[a] - q[a];
    acc += df * df;
  }
  return acc <= r2;
}

/* 1 when some window of the tree lies within squared distance r2 of q. */
int smgb_kd_any_within(const smgb_kd_tree* t, const float* feat,
                       uint32_t dims, const float* q, float r2);

/* Frees the nodes and idx; the tree is empty afterwards. */
void smgb_kd_free(smgb_kd_tree* t);

#endif /* BAKE_KDTREE_H */
