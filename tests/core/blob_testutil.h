/*
 * blob_testutil.h - helpers for tests that take blobs apart: exact-size
 * aligned copies (so valgrind sees any read past the end), section lookup,
 * re-sealing the checksum after planting a bad value.
 */
#ifndef SMG_TESTS_BLOB_TESTUTIL_H
#define SMG_TESTS_BLOB_TESTUTIL_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "blob.h"
#include "fixture_graph.h"
#include "test_env.h"

/* Exactly `size` bytes (never fewer than 1 allocated), 16-byte aligned,
 * holding the first `size` bytes of src (uninitialised when src is NULL). */
static inline unsigned char* test_aligned_copy(const void* src, size_t size) {
  void* p = NULL;
  if (posix_memalign(&p, 16, size ? size : 1) != 0) return NULL;
  if (src && size) memcpy(p, src, size);
  return (unsigned char*)p;
}

static inline smgi_blob_header* test_header(unsigned char* blob) {
  return (smgi_blob_header*)blob;
}

static inline smgi_blob_section* test_table(unsigned char* blob) {
  return (smgi_blob_section*)(blob + sizeof(smgi_blob_header));
}

/* Table entry of `tag`, or NULL. */
static inline smgi_blob_section* test_section(unsigned char* blob,
                                              uint32_t tag) {
  uint32_t i, n = test_header(blob)->section_count;
  for (i = 0; i < n; ++i)
    if (test_table(blob)[i].tag == tag) return &test_table(blob)[i];
  return NULL;
}

/* First byte of section `tag`'s records. */
static inline void* test_section_data(unsigned char* blob, uint32_t tag) {
  smgi_blob_section* s = test_section(blob, tag);
  return s ? blob + s->offset : NULL;
}

/* Recompute the payload checksum after an edit. */
static inline void test_reseal(unsigned char* blob) {
  smgi_blob_header* h = test_header(blob);
  h->checksum = smgi_blob_checksum(blob + h->header_size,
                             (size_t)(h->total_size - h->header_size));
}

#endif /* SMG_TESTS_BLOB_TESTUTIL_H */
