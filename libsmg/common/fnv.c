/*
 * fnv.c - FNV-1a 64-bit, the blob payload checksum. Chosen because it is
 * tiny, has no tables, is byte-order independent in its definition and
 * catches every single-bit flip (each byte step is a bijection of the state).
 */
#include "blob.h"

uint64_t smgi_fnv1a64(const void* data, size_t size) {
  const unsigned char* p = (const unsigned char*)data;
  uint64_t h = 14695981039346656037ull; /* offset basis */
  size_t i;
  for (i = 0; i < size; ++i) {
    h ^= (uint64_t)p[i];
    h *= 1099511628211ull; /* FNV prime */
  }
  return h;
}
