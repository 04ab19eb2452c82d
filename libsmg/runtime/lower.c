/*
 * lower.c - the lower body's timeline (lower.h): locating frames ahead of
 * the playhead and advancing the playhead through the queue of committed
 * edges. Bounded work, no allocation.
 */
#include "lower.h"

int smgi_q_locate(const smgi_lower* l, const smgi_edge* edges, uint32_t k,
                  uint32_t* entry, uint32_t* offset) {
  uint32_t off = (uint32_t)l->t + k;
  for (uint32_t i = 0; i < l->count; ++i) {
    uint32_t fc = edges[smgi_q_at_c(l, i)->edge].frame_count;
    if (off < fc) {
      *entry = i;
      *offset = off;
      return 1;
    }
    off -= fc;
  }
  return 0;
}

void smgi_lower_lag_write_entry(smgi_lower* l, uint32_t i) {
  smgi_qentry* q = smgi_q_at(l, i);
  q->W = smgi_lag_apply(&l->lag, q->W);
  q->M = smgi_lag_apply(&l->lag, q->M);
}

uint32_t smgi_lower_advance(smgi_lower* l, const smgi_edge* edges,
                            float frames) {
  l->t += frames;
  uint32_t pops = 0;
  for (;;) {
    const smgi_qentry* h = smgi_q_at(l, 0);
    float fc = (float)edges[h->edge].frame_count;
    if (l->t < fc) break;
    if (l->count <= 1u) {
      /* dead end in the graph: hold the last frame */
      l->t = fc - 1.0f;
      break;
    }
    l->t -= fc;
    l->node = edges[h->edge].to;
    l->head = (l->head + 1u) & (SMGI_QUEUE_CAP - 1u);
    l->count--;
    l->frames -= edges[h->edge].frame_count;
    ++pops;
  }
  /* the entries that moved to index 0 or 1 from further back */
  for (uint32_t i = pops < 2u ? 2u - pops : 0u;
       pops > 0 && i < 2u && i < l->count; ++i)
    smgi_lower_lag_write_entry(l, i);
  l->style = edges[smgi_q_at(l, 0)->edge].label;
  return pops;
}
