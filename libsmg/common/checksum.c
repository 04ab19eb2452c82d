/*
 * checksum.c - the blob payload checksum ("SMG-WH64").
 *
 * Byte-wise FNV-1a made a full load of a 4-6 MB blob cost ~20 ms (one
 * multiply per byte, one serial dependency chain), 15x more than every
 * structural check together. This is the same FNV step applied to 64-bit
 * little-endian words in eight independent lanes (one per 8 bytes of each
 * 64-byte block), so the CPU overlaps the multiplies: ~15 GB/s here, where
 * four lanes gave ~10 GB/s. The lanes are folded with the same step.
 *
 * Why it still catches every single-bit flip: within a lane each step
 * (xor a word, multiply by an odd constant) is a bijection of the lane
 * state, so a changed word changes that lane's final value; the fold is a
 * bijection in each lane given the others. Errors are detected, not
 * prevented by an adversary: the checksum guards against damage, and
 * every structural check runs regardless (docs/blob-format.md).
 */
#include <string.h>

#include "blob.h"

#define WH_PRIME 1099511628211ull          /* FNV-1a 64 prime (odd) */
#define WH_BASIS 14695981039346656037ull   /* FNV-1a 64 offset basis */
#define WH_LANES 8u

static inline uint64_t load_le64(const unsigned char* p) {
  /* explicit little-endian assembly: same value on any host (compilers
   * turn it into one load on little-endian machines) */
  return (uint64_t)p[0] | ((uint64_t)p[1] << 8) | ((uint64_t)p[2] << 16) |
         ((uint64_t)p[3] << 24) | ((uint64_t)p[4] << 32) |
         ((uint64_t)p[5] << 40) | ((uint64_t)p[6] << 48) |
         ((uint64_t)p[7] << 56);
}

void smgi_wh64_begin(smgi_wh64* h) {
  for (unsigned k = 0; k < WH_LANES; ++k) h->lane[k] = WH_BASIS + k;
}

/* size: a multiple of 64 (whole blocks) */
void smgi_wh64_blocks(smgi_wh64* h, const void* data, size_t size) {
  const unsigned char* p = (const unsigned char*)data;
  /* eight named lanes, not an array: GCC kept the array on the stack, so
   * every step waited on a store and a reload of its lane (the loop ran at
   * a third of the multiplier's rate) */
  uint64_t l0 = h->lane[0], l1 = h->lane[1], l2 = h->lane[2],
           l3 = h->lane[3], l4 = h->lane[4], l5 = h->lane[5],
           l6 = h->lane[6], l7 = h->lane[7];
  for (size_t i = 0; i + 8u * WH_LANES <= size; i += 8u * WH_LANES) {
    const unsigned char* b = p + i;
    l0 = (l0 ^ load_le64(b)) * WH_PRIME;
    l1 = (l1 ^ load_le64(b + 8)) * WH_PRIME;
    l2 = (l2 ^ load_le64(b + 16)) * WH_PRIME;
    l3 = (l3 ^ load_le64(b + 24)) * WH_PRIME;
    l4 = (l4 ^ load_le64(b + 32)) * WH_PRIME;
    l5 = (l5 ^ load_le64(b + 40)) * WH_PRIME;
    l6 = (l6 ^ load_le64(b + 48)) * WH_PRIME;
    l7 = (l7 ^ load_le64(b + 56)) * WH_PRIME;
  }
  h->lane[0] = l0;
  h->lane[1] = l1;
  h->lane[2] = l2;
  h->lane[3] = l3;
  h->lane[4] = l4;
  h->lane[5] = l5;
  h->lane[6] = l6;
  h->lane[7] = l7;
}

/* tail: the last tail_size (< 64) bytes of the total_size */
uint64_t smgi_wh64_end(smgi_wh64* h, const void* tail, size_t tail_size,
                       size_t total_size) {
  const unsigned char* p = (const unsigned char*)tail;
  size_t i = 0, k;
  for (k = 0; i + 8u <= tail_size; i += 8u, ++k)
    h->lane[k] = (h->lane[k] ^ load_le64(p + i)) * WH_PRIME;
  for (; i < tail_size; ++i)
    h->lane[0] = (h->lane[0] ^ (uint64_t)p[i]) * WH_PRIME;
  {
    uint64_t v = WH_BASIS ^ (uint64_t)total_size;
    for (k = 0; k < WH_LANES; ++k) v = (v ^ h->lane[k]) * WH_PRIME;
    return v;
  }
}

uint64_t smgi_blob_checksum(const void* data, size_t size) {
  const size_t whole = size & ~(size_t)(8u * WH_LANES - 1u);
  smgi_wh64 h;
  smgi_wh64_begin(&h);
  smgi_wh64_blocks(&h, data, whole);
  return smgi_wh64_end(&h, (const unsigned char*)data + whole, size - whole,
                       size);
}
