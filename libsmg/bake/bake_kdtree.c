/*
 * bake_kdtree.c - static kd-tree over window features (bake_kdtree.h).
 */
#include "bake_kdtree.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static uint32_t kd_push(smgb_kd_tree* t) {
  if (t->count == t->cap) {
    uint32_t cap = t->cap ? t->cap * 2u : 64u;
    smgb_kd_node* n = realloc(t->nodes, cap * sizeof *n);
    if (!n) return UINT32_MAX;
    t->nodes = n;
    t->cap = cap;
  }
  memset(&t->nodes[t->count], 0, sizeof t->nodes[0]);
  return t->count++;
}

/* Order of two windows along a dimension; ties by index, so that the tree
 * does not depend on the sort's path. */
static int kd_less(const float* fc, uint32_t d, uint32_t dim, uint32_t a,
                   uint32_t b) {
  float va = fc[(size_t)a * d + dim], vb = fc[(size_t)b * d + dim];
  return va < vb || (va == vb && a < b);
}

/* Partition idx[lo, hi) so that the element at `nth` is in its sorted
 * place (quickselect). */
static void kd_select(const float* fc, uint32_t d, uint32_t dim,
                      uint32_t* idx, uint32_t lo, uint32_t hi, uint32_t nth) {
  while (hi - lo > 1) {
    uint32_t mid = lo + (hi - lo) / 2, piv, i, store, tmp;
    /* median of three as the pivot */
    uint32_t a = idx[lo], b = idx[mid], c = idx[hi - 1];
    uint32_t m = kd_less(fc, d, dim, a, b)
                     ? (kd_less(fc, d, dim, b, c) ? mid
                        : kd_less(fc, d, dim, a, c) ? hi - 1 : lo)
                     : (kd_less(fc, d, dim, a, c) ? lo
                        : kd_less(fc, d, dim, b, c) ? hi - 1 : mid);
    piv = idx[m];
    idx[m] = idx[hi - 1];
    idx[hi - 1] = piv;
    store = lo;
    for (i = lo; i + 1 < hi; ++i)
      if (kd_less(fc, d, dim, idx[i], piv)) {
        tmp = idx[i];
        idx[i] = idx[store];
        idx[store++] = tmp;
      }
    idx[hi - 1] = idx[store];
    idx[store] = piv;
    if (store == nth) return;
    if (nth < store)
      hi = store;
    else
      lo = store + 1;
  }
}

static uint32_t kd_build(smgb_kd_tree* t, const float* fc, uint32_t d,
                         uint32_t lo, uint32_t hi, int* ok) {
  uint32_t node = kd_push(t), i, dim, best = 0, mid;
  float spread = -1.0f;
  if (node == UINT32_MAX) {
    *ok = 0;
    return 0;
  }
  t->nodes[node].lo = lo;
  t->nodes[node].hi = hi;
  if (hi - lo <= SMGB_KD_LEAF) return node;
  for (dim = 0; dim < d; ++dim) {
    float mn = INFINITY, mx = -INFINITY;
    for (i = lo; i < hi; ++i) {
      float v = fc[(size_t)t->idx[i] * d + dim];
      if (v < mn) mn = v;
      if (v > mx) mx = v;
    }
    if (mx - mn > spread) {
      spread = mx - mn;
      best = dim;
    }
  }
  mid = lo + (hi - lo) / 2;
  kd_select(fc, d, best, t->idx, lo, hi, mid);
  t->nodes[node].dim = best;
  t->nodes[node].split = fc[(size_t)t->idx[mid] * d + best];
  {
    uint32_t l = kd_build(t, fc, d, lo, mid, ok);
    uint32_t r = *ok ? kd_build(t, fc, d, mid, hi, ok) : 0;
    t->nodes[node].left = l;
    t->nodes[node].right = r;
  }
  return node;
}

int smgb_kd_build(smgb_kd_tree* t, const float* feat, uint32_t dims) {
  int ok = 1;
  t->count = 0;
  if (t->n == 0) return 1;
  kd_build(t, feat, dims, 0, t->n, &ok);
  return ok;
}

static int any_within(const smgb_kd_tree* t, uint32_t node, const float* feat,
                      uint32_t d, const float* q, float r2, float rd,
                      float* off) {
  const smgb_kd_node* n = &t->nodes[node];
  if (!n->left) {
    uint32_t i;
    for (i = n->lo; i < n->hi; ++i)
      if (smgb_kd_within(feat + (size_t)t->idx[i] * d, q, d, r2)) return 1;
    return 0;
  }
  {
    float diff = q[n->dim] - n->split;
    uint32_t near = diff < 0.0f ? n->left : n->right;
    uint32_t far = diff < 0.0f ? n->right : n->left;
    float old = off[n->dim], frd;
    int hit;
    if (any_within(t, near, feat, d, q, r2, rd, off)) return 1;
    frd = rd - old * old + diff * diff;
    if (frd > r2) return 0;
    off[n->dim] = diff;
    hit = any_within(t, far, feat, d, q, r2, frd, off);
    off[n->dim] = old;
    return hit;
  }
}

int smgb_kd_any_within(const smgb_kd_tree* t, const float* feat,
                       uint32_t dims, const float* q, float r2) {
  float off[64];
  if (t->n == 0 || t->count == 0 || dims > 64u) return 0;
  memset(off, 0, dims * sizeof *off);
  return any_within(t, 0, feat, dims, q, r2, 0.0f, off);
}

void smgb_kd_free(smgb_kd_tree* t) {
  free(t->nodes);
  free(t->idx);
  memset(t, 0, sizeof *t);
}
