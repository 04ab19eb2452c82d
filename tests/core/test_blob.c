/*
 * test_blob.c - the graph-blob container: writer determinism, round trip,
 * and the reader's rejection of every kind of damage (truncation, bit
 * flips, planted out-of-range values, misalignment, wrong version).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "blob.h"
#include "blob_testutil.h"
#include "fixture_graph.h"
#include "smg.h"

typedef struct fx {
  fixture_graph* graph;
  unsigned char* blob; /* writer output (malloc-based) */
  size_t size;
} fx;

static int setup(void** state) {
  fx* f = (fx*)calloc(1, sizeof *f);
  void* data = NULL;
  if (!f) return -1;
  f->graph = fixture_graph_new();
  if (!f->graph) return -1;
  if (smgi_blob_write(&f->graph->data, NULL, &data, &f->size, NULL, 0) !=
      SMG_OK)
    return -1;
  f->blob = (unsigned char*)data;
  *state = f;
  return 0;
}

static int teardown(void** state) {
  fx* f = (fx*)*state;
  smgi_blob_free(f->blob, NULL);
  fixture_graph_delete(f->graph);
  free(f);
  return 0;
}

static smg_result read_copy(const unsigned char* blob, size_t size,
                            uint32_t flags, char* err, size_t err_size) {
  unsigned char* c = test_aligned_copy(blob, size);
  smgi_graph_data view;
  smg_result r;
  assert_non_null(c);
  r = smgi_blob_read(c, size, flags, &view, err, err_size);
  free(c);
  return r;
}

/* ---- writer ------------------------------------------------------------- */

static void test_write_is_deterministic_and_aligned(void** state) {
  fx* f = (fx*)*state;
  void* again = NULL;
  size_t size2 = 0, i;
  smgi_blob_header* h = test_header(f->blob);
  assert_int_equal(smgi_blob_write(&f->graph->data, NULL, &again, &size2,
                                   NULL, 0),
                   SMG_OK);
  assert_int_equal(size2, f->size);
  assert_memory_equal(again, f->blob, f->size);
  smgi_blob_free(again, NULL);

  assert_int_equal((uintptr_t)f->blob % 16, 0);
  assert_int_equal(f->size % 16, 0);
  assert_memory_equal(h->magic, "SMGGRAPH", 8);
  assert_int_equal(h->endian, SMGI_BLOB_ENDIAN);
  assert_int_equal(h->version, SMGI_BLOB_VERSION);
  assert_int_equal(h->header_size, 64);
  assert_int_equal(h->total_size, f->size);
  assert_int_equal(h->section_count, 13);
  assert_true(h->checksum ==
              smgi_blob_checksum(f->blob + 64, f->size - 64));
  /* every section 16-aligned, padding after it zero */
  for (i = 0; i < h->section_count; ++i) {
    const smgi_blob_section* s = &test_table(f->blob)[i];
    uint64_t end = s->offset + s->size, pad;
    assert_int_equal(s->alignment, 16);
    assert_int_equal(s->offset % 16, 0);
    for (pad = end; pad % 16 != 0; ++pad) assert_int_equal(f->blob[pad], 0);
  }
}

/* Pinned values: a change here changes the blob format (bump the version). */
static void test_checksum_known_values(void** state) {
  unsigned char b[100];
  int i;
  (void)state;
  for (i = 0; i < 100; ++i) b[i] = (unsigned char)(i * 37 + 11);
  assert_true(smgi_blob_checksum("", 0) == 0xd14df2d7dd9cab2dull);
  assert_true(smgi_blob_checksum("a", 1) == 0x7dfa6149173632e5ull);
  assert_true(smgi_blob_checksum("foobar", 6) == 0xdccbf478a6d13f4eull);
  assert_true(smgi_blob_checksum(b, 100) == 0x9322354abb6d3a49ull);
}

/* Every single-bit flip changes the checksum, whichever path (64-byte
 * blocks, 8-byte tail words, trailing bytes) hashes the flipped byte; so
 * does swapping two words of different lanes or appending a zero byte. */
static void test_checksum_detects_flips(void** state) {
  unsigned char b[101];
  uint64_t ref;
  int i, bit;
  (void)state;
  for (i = 0; i < 101; ++i) b[i] = (unsigned char)(i * 91 + 7);
  ref = smgi_blob_checksum(b, 101);
  for (i = 0; i < 101; ++i)
    for (bit = 0; bit < 8; ++bit) {
      b[i] ^= (unsigned char)(1u << bit);
      assert_true(smgi_blob_checksum(b, 101) != ref);
      b[i] ^= (unsigned char)(1u << bit);
    }
  {
    unsigned char w[64];
    memcpy(w, b, 64);
    memcpy(w, b + 8, 8);
    memcpy(w + 8, b, 8);
    assert_true(smgi_blob_checksum(w, 64) != smgi_blob_checksum(b, 64));
  }
  assert_true(smgi_blob_checksum(b, 64) != smgi_blob_checksum(b, 65) ||
              b[64] != 0);
  b[64] = 0;
  assert_true(smgi_blob_checksum(b, 64) != smgi_blob_checksum(b, 65));
}

/* The checksum in pieces (begin, whole 64-byte blocks in any grouping,
 * end with the tail) is the one-shot checksum, for every length around
 * the block and word boundaries. */
static void test_checksum_in_pieces(void** state) {
  unsigned char b[300];
  (void)state;
  for (int i = 0; i < 300; ++i) b[i] = (unsigned char)(i * 53 + 29);
  for (size_t n = 0; n <= 300; ++n) {
    const size_t whole = n & ~(size_t)63u;
    for (size_t cut = 0; cut <= whole; cut += 64) {
      smgi_wh64 h;
      smgi_wh64_begin(&h);
      smgi_wh64_blocks(&h, b, cut);
      smgi_wh64_blocks(&h, b + cut, whole - cut);
      assert_true(smgi_wh64_end(&h, b + whole, n - whole, n) ==
                  smgi_blob_checksum(b, n));
    }
  }
}

/* POSE and FRMI are checked as the checksum pass reaches them, section
 * by section; the reason is still that of the first bad frame, POSE
 * before FRMI within a frame, with or without the checksum. */
static void test_first_bad_frame_is_reported(void** state) {
  fx* f = (fx*)*state;
  const float nan = NAN;
  /* (pose frame, frame-info frame, expected text) */
  const struct {
    uint32_t pose, frmi;
    const char* needle;
  } cases[] = {{7, 3, "FRMI[3].phase"},
               {3, 7, "POSE[3] root"},
               {5, 5, "POSE[5] root"},
               {150, 149, "FRMI[149].phase"}};
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
    unsigned char* c = test_aligned_copy(f->blob, f->size);
    const smgi_blob_section* ps = test_section(c, SMGI_SEC_POSE);
    smgi_frame* fr = (smgi_frame*)test_section_data(c, SMGI_SEC_FRMI);
    smgi_graph_data v;
    char err[256];
    memcpy(c + ps->offset + (uint64_t)cases[i].pose * ps->record_size + 4,
           &nan, 4);
    fr[cases[i].frmi].phase = nan;
    test_reseal(c);
    for (int skip = 0; skip < 2; ++skip) {
      smg_result r = smgi_blob_read(c, f->size,
                                    skip ? SMG_GRAPH_SKIP_CHECKSUM : 0u, &v,
                                    err, sizeof err);
      assert_int_equal(r, SMG_ERROR_BLOB_VALUE);
      if (!strstr(err, cases[i].needle))
        fail_msg("expected '%s', got '%s'", cases[i].needle, err);
    }
    free(c);
  }
}

/* Blob contents equal the arrays they were written from, and writing the
 * read view again gives the same bytes. */
static void test_round_trip(void** state) {
  fx* f = (fx*)*state;
  const smgi_graph_data* a = &f->graph->data;
  smgi_graph_data b;
  void* again = NULL;
  size_t size2 = 0;
  char err[256];
  assert_int_equal(smgi_blob_read(f->blob, f->size, 0, &b, err, sizeof err),
                   SMG_OK);
  assert_string_equal(err, "");
  assert_memory_equal(b.info, a->info, sizeof(smgi_info));
  assert_int_equal(b.strings_size, a->strings_size);
  assert_memory_equal(b.strings, a->strings, a->strings_size);
#define SAME(p, n, T)                                   \
  assert_int_equal(b.n, a->n);                          \
  assert_memory_equal(b.p, a->p, sizeof(T) * a->n)
  SAME(joints, joint_count, smgi_joint);
  SAME(styles, style_count, smgi_label);
  SAME(actions, action_count, smgi_label);
  SAME(clips, clip_count, smgi_clip);
  SAME(frames, frame_count, smgi_frame);
  SAME(lower_nodes, lower_node_count, smgi_node);
  SAME(lower_edges, lower_edge_count, smgi_edge);
  SAME(upper_nodes, upper_node_count, smgi_node);
  SAME(upper_edges, upper_edge_count, smgi_edge);
  SAME(splices, splice_count, smgi_splice);
#undef SAME
  assert_memory_equal(b.poses, a->poses,
                      (size_t)a->frame_count *
                          SMGI_POSE_RECORD_SIZE(a->joint_count));
  /* and decode to the fixture's float poses: roots exact, rotations within
   * the packing's error (quat_pack.h) */
  {
    uint32_t fr, j;
    double worst = 0.0;
    for (fr = 0; fr < b.frame_count; ++fr) {
      float p[SMGI_POSE_FLOATS(FIXTURE_JOINTS)];
      const float* src = f->graph->poses + (size_t)fr * FIXTURE_STRIDE;
      smgi_pose_unpack(smgi_pose_record(&b, fr), b.joint_count, p);
      assert_memory_equal(p, src, 3 * sizeof(float));
      for (j = 0; j < FIXTURE_JOINTS; ++j) {
        /* angle of conj(y) x: 2 asin |vector part| (both unit) */
        const float* x = p + 3 + 4 * j;
        const float* y = src + 3 + 4 * j;
        double v0 = (double)y[3] * x[0] - (double)y[0] * x[3] -
                    (double)y[1] * x[2] + (double)y[2] * x[1];
        double v1 = (double)y[3] * x[1] - (double)y[1] * x[3] -
                    (double)y[2] * x[0] + (double)y[0] * x[2];
        double v2 = (double)y[3] * x[2] - (double)y[2] * x[3] -
                    (double)y[0] * x[1] + (double)y[1] * x[0];
        double angle = 2.0 * asin(fmin(1.0, sqrt(v0 * v0 + v1 * v1 + v2 * v2)));
        if (angle > worst) worst = angle;
      }
    }
    assert_true(worst <= 1.3e-4); /* quat_pack.h's bound */
  }
  /* load in place: the view points into the blob */
  assert_ptr_equal((const void*)b.info,
                   f->blob + test_section(f->blob, SMGI_SEC_INFO)->offset);
  assert_int_equal(smgi_blob_write(&b, NULL, &again, &size2, NULL, 0),
                   SMG_OK);
  assert_int_equal(size2, f->size);
  assert_memory_equal(again, f->blob, f->size);
  smgi_blob_free(again, NULL);
}

typedef struct counting_alloc {
  int allocs, frees, fail_at;
} counting_alloc;

static void* count_alloc(size_t size, size_t align, void* user) {
  counting_alloc* c = (counting_alloc*)user;
  void* p = NULL;
  if (c->fail_at >= 0 && c->allocs >= c->fail_at) return NULL;
  c->allocs++;
  if (posix_memalign(&p, align < sizeof(void*) ? sizeof(void*) : align,
                     size) != 0)
    return NULL;
  return p;
}

static void count_free(void* p, void* user) {
  counting_alloc* c = (counting_alloc*)user;
  c->frees++;
  free(p);
}

static void test_write_uses_allocator_and_reports_oom(void** state) {
  fx* f = (fx*)*state;
  counting_alloc c = {0, 0, -1};
  smg_allocator a = {count_alloc, count_free, &c};
  smg_allocator half = {count_alloc, NULL, &c};
  void* data = NULL;
  size_t size = 0;
  assert_int_equal(smgi_blob_write(&f->graph->data, &a, &data, &size, NULL,
                                   0),
                   SMG_OK);
  assert_int_equal(c.allocs, 1);
  assert_memory_equal(data, f->blob, f->size);
  smgi_blob_free(data, &a);
  assert_int_equal(c.frees, 1);

  c.fail_at = 0;
  data = NULL;
  assert_int_equal(smgi_blob_write(&f->graph->data, &a, &data, &size, NULL,
                                   0),
                   SMG_ERROR_OUT_OF_MEMORY);
  assert_null(data);
  assert_int_equal(smgi_blob_write(&f->graph->data, &half, &data, &size,
                                   NULL, 0),
                   SMG_ERROR_INVALID_ARGUMENT);
}

static void test_write_rejects_bad_arguments(void** state) {
  fx* f = (fx*)*state;
  smgi_graph_data d = f->graph->data;
  void* data = NULL;
  size_t size = 0;
  char err[128];
  assert_int_equal(smgi_blob_write(NULL, NULL, &data, &size, NULL, 0),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smgi_blob_write(&d, NULL, NULL, &size, NULL, 0),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smgi_blob_write(&d, NULL, &data, NULL, NULL, 0),
                   SMG_ERROR_INVALID_ARGUMENT);
  d.lower_edges = NULL; /* count stays 6 */
  assert_int_equal(smgi_blob_write(&d, NULL, &data, &size, err, sizeof err),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_non_null(strstr(err, "LEDG"));
  d = f->graph->data;
  d.info = NULL;
  assert_int_equal(smgi_blob_write(&d, NULL, &data, &size, NULL, 0),
                   SMG_ERROR_INVALID_ARGUMENT);
  d = f->graph->data;
  d.joint_count = 0x40000000u; /* pose record would not fit in 32 bits */
  assert_int_equal(smgi_blob_write(&d, NULL, &data, &size, NULL, 0),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_null(data);
}

/* The writer refuses to produce a blob the reader would reject. */
static void test_write_validates_its_output(void** state) {
  fx* f = (fx*)*state;
  void* data = NULL;
  size_t size = 0;
  char err[256];
  f->graph->lower_nodes[1].frame = FIXTURE_FRAMES;
  assert_int_equal(smgi_blob_write(&f->graph->data, NULL, &data, &size, err,
                                   sizeof err),
                   SMG_ERROR_BLOB_INDEX);
  assert_null(data);
  assert_non_null(strstr(err, "LNOD[1].frame"));
  f->graph->lower_nodes[1].frame = 90;
}

/* A graph with no nodes is valid when it has no edges either. */
static void test_empty_graphs(void** state) {
  fx* f = (fx*)*state;
  smgi_graph_data d = f->graph->data, back;
  void* data = NULL;
  size_t size = 0;
  d.lower_node_count = d.lower_edge_count = 0;
  d.upper_node_count = d.upper_edge_count = 0;
  d.splice_count = 0;
  assert_int_equal(smgi_blob_write(&d, NULL, &data, &size, NULL, 0), SMG_OK);
  assert_int_equal(smgi_blob_read(data, size, 0, &back, NULL, 0), SMG_OK);
  assert_int_equal(back.lower_node_count, 0);
  assert_int_equal(back.splice_count, 0);
  smgi_blob_free(data, NULL);
  data = NULL;
  d.lower_edge_count = 1; /* an edge without nodes */
  assert_int_equal(smgi_blob_write(&d, NULL, &data, &size, NULL, 0),
                   SMG_ERROR_BLOB_INDEX);
  assert_null(data);
}

/* ---- reader: container ---------------------------------------------------- */

static void test_read_rejects_bad_arguments(void** state) {
  fx* f = (fx*)*state;
  smgi_graph_data v;
  assert_int_equal(smgi_blob_read(NULL, f->size, 0, &v, NULL, 0),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smgi_blob_read(f->blob, f->size, 0, NULL, NULL, 0),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smgi_blob_read(f->blob, f->size, 0x80, &v, NULL, 0),
                   SMG_ERROR_INVALID_ARGUMENT);
  /* error buffer of size 1 and 0 are honoured */
  {
    char one[1] = {'x'};
    assert_int_equal(smgi_blob_read(f->blob, 7, 0, &v, one, 1),
                     SMG_ERROR_BLOB_TRUNCATED);
    assert_int_equal(one[0], '\0');
    assert_int_equal(smgi_blob_read(f->blob, 7, 0, &v, one, 0),
                     SMG_ERROR_BLOB_TRUNCATED);
  }
}

static void test_misaligned_memory(void** state) {
  fx* f = (fx*)*state;
  unsigned char* buf = test_aligned_copy(NULL, f->size + 16);
  smgi_graph_data v;
  size_t shift;
  assert_non_null(buf);
  for (shift = 1; shift < 16; ++shift) {
    memcpy(buf + shift, f->blob, f->size);
    assert_int_equal(smgi_blob_read(buf + shift, f->size, 0, &v, NULL, 0),
                     SMG_ERROR_BLOB_ALIGNMENT);
  }
  free(buf);
}

/* Every proper prefix of a valid blob fails cleanly (exact-size copies, so
 * valgrind sees any read past the end). Under SMG_TEST_QUICK the long tail
 * is sampled. */
static void test_every_truncation_fails(void** state) {
  fx* f = (fx*)*state;
  size_t len, tested = 0;
  int quick = smgt_quick();
  for (len = 0; len < f->size; ++len) {
    if (quick && len > 2048 && len % 97 != 0 && len + 64 < f->size) continue;
    assert_true(read_copy(f->blob, len, 0, NULL, 0) != SMG_OK);
    assert_true(read_copy(f->blob, len, SMG_GRAPH_SKIP_CHECKSUM, NULL, 0) !=
                SMG_OK);
    ++tested;
  }
  assert_true(tested > 2048);
  assert_int_equal(read_copy(f->blob, 7, 0, NULL, 0),
                   SMG_ERROR_BLOB_TRUNCATED);
  assert_int_equal(read_copy(f->blob, 63, 0, NULL, 0),
                   SMG_ERROR_BLOB_TRUNCATED);
  assert_int_equal(read_copy(f->blob, f->size - 16, 0, NULL, 0),
                   SMG_ERROR_BLOB_TRUNCATED);
}

/* A truncated blob whose header was patched to the new length (and
 * re-sealed) must still fail: its sections now run past the end. */
static void test_truncation_with_patched_header_fails(void** state) {
  fx* f = (fx*)*state;
  size_t len;
  for (len = 64; len < f->size; len += smgt_quick() ? 256 : 16) {
    unsigned char* c = test_aligned_copy(f->blob, len);
    smgi_graph_data v;
    smg_result r;
    test_header(c)->total_size = len;
    test_reseal(c);
    r = smgi_blob_read(c, len, 0, &v, NULL, 0);
    assert_true(r == SMG_ERROR_BLOB_SECTION);
    free(c);
  }
}

/* Any single bit flip in the 64-byte header is detected: the header is not
 * covered by the checksum, so each field is checked by value. */
static void test_header_bit_flips(void** state) {
  fx* f = (fx*)*state;
  unsigned char* c = test_aligned_copy(f->blob, f->size);
  smgi_graph_data v;
  size_t bit;
  for (bit = 0; bit < 64 * 8; ++bit) {
    c[bit / 8] ^= (unsigned char)(1u << (bit % 8));
    assert_true(smgi_blob_read(c, f->size, 0, &v, NULL, 0) != SMG_OK);
    c[bit / 8] ^= (unsigned char)(1u << (bit % 8));
  }
  assert_int_equal(smgi_blob_read(c, f->size, 0, &v, NULL, 0), SMG_OK);
  free(c);
}

/* Bit flips anywhere after the header (table, records, padding) are caught
 * by the checksum. Every bit of the table, then bits spread over every
 * section. */
static void test_payload_bit_flips_fail_checksum(void** state) {
  fx* f = (fx*)*state;
  unsigned char* c = test_aligned_copy(f->blob, f->size);
  smgi_graph_data v;
  uint32_t i, n = test_header(c)->section_count;
  size_t bit, table_bits = (size_t)n * sizeof(smgi_blob_section) * 8;
  size_t step = smgt_quick() ? 13 : 1;
  uint64_t rng = 0x9e3779b97f4a7c15ull;
  for (bit = 0; bit < table_bits; bit += step) {
    size_t byte = 64 + bit / 8;
    c[byte] ^= (unsigned char)(1u << (bit % 8));
    assert_int_equal(smgi_blob_read(c, f->size, 0, &v, NULL, 0),
                     SMG_ERROR_BLOB_CHECKSUM);
    c[byte] ^= (unsigned char)(1u << (bit % 8));
  }
  for (i = 0; i < n; ++i) {
    smgi_blob_section s = test_table(c)[i];
    int k;
    if (s.size == 0) continue;
    for (k = 0; k < (smgt_quick() ? 4 : 32); ++k) {
      size_t byte;
      unsigned b;
      rng = rng * 6364136223846793005ull + 1442695040888963407ull;
      byte = (size_t)(s.offset + (rng >> 33) % s.size);
      b = (unsigned)(rng >> 20) % 8u;
      c[byte] ^= (unsigned char)(1u << b);
      assert_int_equal(smgi_blob_read(c, f->size, 0, &v, NULL, 0),
                       SMG_ERROR_BLOB_CHECKSUM);
      /* without the checksum the reader must still not crash */
      (void)smgi_blob_read(c, f->size, SMG_GRAPH_SKIP_CHECKSUM, &v, NULL, 0);
      c[byte] ^= (unsigned char)(1u << b);
    }
  }
  /* padding between sections is covered too */
  {
    const smgi_blob_section* s = test_section(c, SMGI_SEC_STRS);
    size_t pad = (size_t)(s->offset + s->size);
    assert_true(pad % 16 != 0);
    c[pad] = 0x5a;
    assert_int_equal(smgi_blob_read(c, f->size, 0, &v, NULL, 0),
                     SMG_ERROR_BLOB_CHECKSUM);
  }
  free(c);
}

/* Same single-bit flips in the table with the checksum skipped: the
 * structural checks alone reject every one of them (a moved offset always
 * overlaps a neighbour or leaves the blob, because padding is < 16 bytes). */
static void test_table_bit_flips_without_checksum(void** state) {
  fx* f = (fx*)*state;
  unsigned char* c = test_aligned_copy(f->blob, f->size);
  smgi_graph_data v;
  size_t bit, table_bits =
                  (size_t)test_header(c)->section_count * 32 * 8,
              rejected = 0, total = 0;
  for (bit = 0; bit < table_bits; bit += smgt_quick() ? 7 : 1) {
    size_t byte = 64 + bit / 8;
    c[byte] ^= (unsigned char)(1u << (bit % 8));
    if (smgi_blob_read(c, f->size, SMG_GRAPH_SKIP_CHECKSUM, &v, NULL, 0) !=
        SMG_OK)
      ++rejected;
    ++total;
    c[byte] ^= (unsigned char)(1u << (bit % 8));
  }
  assert_int_equal(rejected, total);
  free(c);
}

typedef struct header_case {
  const char* what;
  size_t offset; /* into the header */
  uint32_t value;
  smg_result expect;
} header_case;

static void test_header_fields(void** state) {
  fx* f = (fx*)*state;
  const header_case cases[] = {
      {"magic", 0, 0x4b4b4b4bu /* "KKKK" */, SMG_ERROR_BLOB_MAGIC},
      {"endian swapped", 8, 0x04030201u, SMG_ERROR_BLOB_ENDIAN},
      {"version 0", 12, 0u, SMG_ERROR_BLOB_VERSION},
      {"version 1 (float rotations)", 12, 1u, SMG_ERROR_BLOB_VERSION},
      {"version max+1", 12, SMG_BLOB_VERSION_MAX + 1u,
       SMG_ERROR_BLOB_VERSION},
      {"header_size", 24, 80u, SMG_ERROR_BLOB_VALUE},
      {"section_count too big", 28, SMGI_MAX_SECTIONS + 1u,
       SMG_ERROR_BLOB_SECTION},
      {"section_count 12", 28, 12u, SMG_ERROR_BLOB_SECTION},
      {"flags", 40, 1u, SMG_ERROR_BLOB_VALUE},
      {"reserved[4]", 60, 7u, SMG_ERROR_BLOB_VALUE},
  };
  size_t i;
  for (i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
    unsigned char* c = test_aligned_copy(f->blob, f->size);
    char err[256];
    memcpy(c + cases[i].offset, &cases[i].value, 4);
    test_reseal(c);
    if (smgi_blob_read(c, f->size, 0, &(smgi_graph_data){0}, err,
                       sizeof err) != cases[i].expect)
      fail_msg("header case '%s': got '%s'", cases[i].what, err);
    free(c);
  }
  /* total_size larger than the bytes given, smaller, not a multiple of 16 */
  {
    unsigned char* c = test_aligned_copy(f->blob, f->size);
    smgi_graph_data v;
    test_header(c)->total_size = f->size + 16;
    assert_int_equal(smgi_blob_read(c, f->size, 0, &v, NULL, 0),
                     SMG_ERROR_BLOB_TRUNCATED);
    test_header(c)->total_size = f->size - 16;
    assert_int_equal(smgi_blob_read(c, f->size, 0, &v, NULL, 0),
                     SMG_ERROR_BLOB_VALUE);
    free(c);
    c = test_aligned_copy(NULL, f->size + 8);
    memcpy(c, f->blob, f->size);
    memset(c + f->size, 0, 8);
    test_header(c)->total_size = f->size + 8;
    assert_int_equal(smgi_blob_read(c, f->size + 8, 0, &v, NULL, 0),
                     SMG_ERROR_BLOB_VALUE);
    free(c);
  }
  /* wrong checksum */
  {
    unsigned char* c = test_aligned_copy(f->blob, f->size);
    smgi_graph_data v;
    test_header(c)->checksum ^= 1u;
    assert_int_equal(smgi_blob_read(c, f->size, 0, &v, NULL, 0),
                     SMG_ERROR_BLOB_CHECKSUM);
    assert_int_equal(
        smgi_blob_read(c, f->size, SMG_GRAPH_SKIP_CHECKSUM, &v, NULL, 0),
        SMG_OK);
    free(c);
  }
}

/* A version-1 blob (float rotations) is refused with the version code and
 * a reason that says what to do; the same through the public loader. */
static void test_version_1_is_refused(void** state) {
  fx* f = (fx*)*state;
  unsigned char* c = test_aligned_copy(f->blob, f->size);
  smgi_graph_data v;
  smg_graph* g = NULL;
  char err[256];
  test_header(c)->version = 1;
  test_reseal(c);
  assert_int_equal(smgi_blob_read(c, f->size, 0, &v, err, sizeof err),
                   SMG_ERROR_BLOB_VERSION);
  assert_non_null(strstr(err, "header.version is 1"));
  assert_non_null(strstr(err, "re-bake"));
  assert_int_equal(smg_graph_load_memory(c, f->size, NULL, &g),
                   SMG_ERROR_BLOB_VERSION);
  assert_null(g);
  free(c);
}

/* Rotations carry no invalid values: random bytes in every packed rotation
 * of every frame still load (checksum re-sealed), and a character walking
 * and splicing on that graph gets finite unit rotations. */
static void test_any_rotation_bits_load(void** state) {
  fx* f = (fx*)*state;
  unsigned char* c = test_aligned_copy(f->blob, f->size);
  const smgi_blob_section* s = test_section(c, SMGI_SEC_POSE);
  static const float path[] = {0, 0, 0, 2, 1, 4, 3, 5};
  float root[3], rot[4 * FIXTURE_JOINTS];
  uint64_t rng = 0x2545f4914f6cdd1dull;
  smgi_graph_data v;
  smg_graph* g = NULL;
  smg_character* ch = NULL;
  uint32_t fr, j, id, step;
  for (fr = 0; fr < s->count; ++fr) {
    unsigned char* rec = c + s->offset + (uint64_t)fr * s->record_size;
    for (j = SMGI_POSE_ROT_OFFSET;
         j < SMGI_POSE_ROT_OFFSET + SMGI_QPACK_BYTES * FIXTURE_JOINTS; ++j) {
      rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
      /* a few frames all-ones or all-zeros: the range ends */
      rec[j] = fr % 16 == 3 ? 0xff : fr % 16 == 4 ? 0x00
                                                  : (unsigned char)(rng >> 24);
    }
  }
  test_reseal(c);
  assert_int_equal(smgi_blob_read(c, f->size, 0, &v, NULL, 0), SMG_OK);
  assert_int_equal(smg_graph_load_memory(c, f->size, NULL, &g), SMG_OK);
  assert_int_equal(smg_character_create(g, NULL, &ch), SMG_OK);
  assert_int_equal(smg_character_set_path(ch, path, 4), SMG_OK);
  assert_int_equal(smg_character_add_splice(ch, 0.5f, 1, &id), SMG_OK);
  for (step = 0; step < 90; ++step) {
    assert_int_equal(smg_character_step(ch, 1.0f / 30.0f), SMG_OK);
    assert_int_equal(
        smg_character_get_local_pose(ch, root, rot, FIXTURE_JOINTS), SMG_OK);
    for (j = 0; j < FIXTURE_JOINTS; ++j) {
      const float* q = rot + 4 * j;
      float n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
      assert_true(isfinite(n2) && fabsf(n2 - 1.0f) < 1e-4f);
    }
    assert_true(isfinite(root[0]) && isfinite(root[1]) && isfinite(root[2]));
  }
  smg_character_destroy(ch);
  smg_graph_destroy(g);
  free(c);
}

/* Table entries: alignment, bounds, overlaps, duplicates, record sizes. */
typedef void (*table_edit)(unsigned char* blob);

static void edit_align8(unsigned char* b) {
  test_section(b, SMGI_SEC_JNTS)->alignment = 8;
}
static void edit_align_npot(unsigned char* b) {
  test_section(b, SMGI_SEC_JNTS)->alignment = 48;
}
static void edit_offset_misaligned(unsigned char* b) {
  test_section(b, SMGI_SEC_JNTS)->offset += 4;
}
static void edit_overlap(unsigned char* b) {
  test_section(b, SMGI_SEC_LNOD)->offset += 16;
}
static void edit_in_header(unsigned char* b) {
  test_section(b, SMGI_SEC_SPLC)->offset = 0;
}
static void edit_past_end(unsigned char* b) {
  test_section(b, SMGI_SEC_SPLC)->offset = test_header(b)->total_size;
}
static void edit_size_huge(unsigned char* b) {
  smgi_blob_section* s = test_section(b, SMGI_SEC_SPLC);
  s->count = 0xffffffffu;
  s->size = (uint64_t)s->count * s->record_size;
}
static void edit_size_mismatch(unsigned char* b) {
  test_section(b, SMGI_SEC_CLIP)->size -= 4;
}
static void edit_duplicate(unsigned char* b) {
  test_section(b, SMGI_SEC_SPLC)->tag = SMGI_SEC_UEDG;
}
static void edit_missing(unsigned char* b) {
  test_section(b, SMGI_SEC_STYL)->tag = SMGI_FOURCC('X', 'X', 'X', 'X');
}
static void edit_record_size(unsigned char* b) {
  smgi_blob_section* s = test_section(b, SMGI_SEC_JNTS);
  s->record_size = 28;
  s->count = (uint32_t)(s->size / 28);
  s->size = (uint64_t)s->count * 28;
}
static void edit_pose_record(unsigned char* b) {
  smgi_blob_section* s = test_section(b, SMGI_SEC_POSE);
  s->record_size -= 16;
  s->size = (uint64_t)s->count * s->record_size;
}
static void edit_frmi_count(unsigned char* b) {
  smgi_blob_section* s = test_section(b, SMGI_SEC_FRMI);
  s->count -= 1;
  s->size -= sizeof(smgi_frame);
}
static void edit_info_count(unsigned char* b) {
  smgi_blob_section* s = test_section(b, SMGI_SEC_INFO);
  s->count = 0;
  s->size = 0;
}

static void test_table_entries(void** state) {
  fx* f = (fx*)*state;
  const struct {
    const char* what;
    table_edit edit;
    smg_result expect;
  } cases[] = {
      {"alignment 8", edit_align8, SMG_ERROR_BLOB_ALIGNMENT},
      {"alignment 48", edit_align_npot, SMG_ERROR_BLOB_ALIGNMENT},
      {"offset misaligned", edit_offset_misaligned, SMG_ERROR_BLOB_ALIGNMENT},
      {"overlap", edit_overlap, SMG_ERROR_BLOB_SECTION},
      {"inside header", edit_in_header, SMG_ERROR_BLOB_SECTION},
      {"past end", edit_past_end, SMG_ERROR_BLOB_SECTION},
      {"huge count", edit_size_huge, SMG_ERROR_BLOB_SECTION},
      {"size != count*record", edit_size_mismatch, SMG_ERROR_BLOB_SECTION},
      {"duplicate tag", edit_duplicate, SMG_ERROR_BLOB_SECTION},
      {"missing STYL", edit_missing, SMG_ERROR_BLOB_SECTION},
      {"JNTS record_size", edit_record_size, SMG_ERROR_BLOB_SECTION},
      {"POSE record_size", edit_pose_record, SMG_ERROR_BLOB_SECTION},
      {"FRMI count", edit_frmi_count, SMG_ERROR_BLOB_SECTION},
      {"INFO count 0", edit_info_count, SMG_ERROR_BLOB_SECTION},
  };
  size_t i;
  for (i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
    unsigned char* c = test_aligned_copy(f->blob, f->size);
    smgi_graph_data v;
    char err[256];
    smg_result r;
    cases[i].edit(c);
    test_reseal(c);
    r = smgi_blob_read(c, f->size, 0, &v, err, sizeof err);
    if (r != cases[i].expect)
      fail_msg("table case '%s': got %d '%s'", cases[i].what, (int)r, err);
    r = smgi_blob_read(c, f->size, SMG_GRAPH_SKIP_CHECKSUM, &v, NULL, 0);
    assert_int_equal(r, cases[i].expect);
    free(c);
  }
}

/* An unknown extra section is skipped (forward compatibility): insert a
 * table entry, shift every section by one entry (32 bytes, keeps 16-byte
 * alignment) and append the new section's 16 bytes at the end. */
static void test_unknown_section_is_ignored(void** state) {
  fx* f = (fx*)*state;
  const smgi_blob_header* old = test_header(f->blob);
  size_t table = 64 + 32 * (size_t)old->section_count;
  size_t size = f->size + 32 + 16;
  unsigned char* c = test_aligned_copy(NULL, size);
  smgi_graph_data v;
  smgi_blob_section extra;
  smgi_blob_header* h;
  uint32_t i;
  assert_non_null(c);
  memset(c, 0, size);
  memcpy(c, f->blob, table);
  memcpy(c + table + 32, f->blob + table, f->size - table);
  h = test_header(c);
  for (i = 0; i < h->section_count; ++i) test_table(c)[i].offset += 32;
  memset(&extra, 0, sizeof extra);
  extra.tag = SMGI_FOURCC('N', 'E', 'W', '!');
  extra.alignment = 16;
  extra.offset = f->size + 32;
  extra.size = 4;
  extra.count = 1;
  extra.record_size = 4;
  memcpy(c + table, &extra, sizeof extra);
  h->section_count += 1;
  h->total_size = size;
  test_reseal(c);
  assert_int_equal(smgi_blob_read(c, size, 0, &v, NULL, 0), SMG_OK);
  assert_int_equal(v.joint_count, FIXTURE_JOINTS);
  assert_int_equal(v.splice_count, FIXTURE_SPLICES);
  free(c);
}

/* ---- reader: record contents ---------------------------------------------- */

enum { U32, I32, F32 };

typedef struct plant {
  const char* what;
  uint32_t tag;
  uint32_t record;
  size_t field; /* byte offset in the record */
  int kind;
  uint32_t u;
  float f;
  smg_result expect;
  const char* needle; /* must appear in the error text */
} plant;

#define P_U(w, tag, rec, T, fld, val, exp, nd) \
  {w, tag, rec, offsetof(T, fld), U32, (uint32_t)(val), 0.0f, exp, nd}
#define P_F(w, tag, rec, T, fld, val, exp, nd) \
  {w, tag, rec, offsetof(T, fld), F32, 0u, (float)(val), exp, nd}

static void apply_plant(unsigned char* b, const plant* p) {
  smgi_blob_section* s = test_section(b, p->tag);
  unsigned char* at;
  assert_non_null(s);
  assert_true(p->record < s->count);
  at = b + s->offset + (uint64_t)p->record * s->record_size + p->field;
  if (p->kind == F32)
    memcpy(at, &p->f, 4);
  else
    memcpy(at, &p->u, 4);
}

static void test_planted_values(void** state) {
  fx* f = (fx*)*state;
  const float inf = INFINITY, nan = NAN;
  const uint32_t punch_name = f->graph->actions[1].name;
  const uint32_t strs = f->graph->data.strings_size;
  const plant plants[] = {
      /* INFO */
      P_F("frame_rate 0", SMGI_SEC_INFO, 0, smgi_info, frame_rate, 0,
          SMG_ERROR_BLOB_VALUE, "frame_rate"),
      P_F("frame_rate nan", SMGI_SEC_INFO, 0, smgi_info, frame_rate, nan,
          SMG_ERROR_BLOB_VALUE, "frame_rate"),
      P_F("frame_rate 5000", SMGI_SEC_INFO, 0, smgi_info, frame_rate, 5000,
          SMG_ERROR_BLOB_VALUE, "frame_rate"),
      P_U("joint_count", SMGI_SEC_INFO, 0, smgi_info, joint_count, 30,
          SMG_ERROR_BLOB_SECTION, "joint_count"),
      P_U("pelvis", SMGI_SEC_INFO, 0, smgi_info, pelvis_joint, 31,
          SMG_ERROR_BLOB_INDEX, "pelvis_joint"),
      P_U("spine base", SMGI_SEC_INFO, 0, smgi_info, spine_base_joint,
          0xffffffffu, SMG_ERROR_BLOB_INDEX, "spine_base_joint"),
      P_U("left leg", SMGI_SEC_INFO, 0, smgi_info, left_leg[2], 31,
          SMG_ERROR_BLOB_INDEX, "left_leg[2]"),
      P_U("right leg", SMGI_SEC_INFO, 0, smgi_info, right_leg[3], 99,
          SMG_ERROR_BLOB_INDEX, "right_leg[3]"),
      P_F("leg_length inf", SMGI_SEC_INFO, 0, smgi_info, leg_length, inf,
          SMG_ERROR_BLOB_VALUE, "leg_length"),
      P_F("window negative", SMGI_SEC_INFO, 0, smgi_info, window_seconds, -1,
          SMG_ERROR_BLOB_VALUE, "window_seconds"),
      /* STRS */
      {"STRS unterminated", SMGI_SEC_STRS, strs - 1, 0, U32, 0x78787878u, 0,
       SMG_ERROR_BLOB_VALUE, "STRS"},
      /* JNTS */
      P_U("root parent 0", SMGI_SEC_JNTS, 0, smgi_joint, parent, 0,
          SMG_ERROR_BLOB_INDEX, "JNTS[0].parent"),
      P_U("parent self", SMGI_SEC_JNTS, 5, smgi_joint, parent, 5,
          SMG_ERROR_BLOB_INDEX, "JNTS[5].parent"),
      P_U("parent after child", SMGI_SEC_JNTS, 5, smgi_joint, parent, 9,
          SMG_ERROR_BLOB_INDEX, "JNTS[5].parent"),
      P_U("parent -1 not root", SMGI_SEC_JNTS, 3, smgi_joint, parent,
          0xffffffffu, SMG_ERROR_BLOB_INDEX, "JNTS[3].parent"),
      P_U("parent -2", SMGI_SEC_JNTS, 3, smgi_joint, parent, 0xfffffffeu,
          SMG_ERROR_BLOB_INDEX, "JNTS[3].parent"),
      P_U("joint name", SMGI_SEC_JNTS, 4, smgi_joint, name, strs,
          SMG_ERROR_BLOB_INDEX, "JNTS[4].name"),
      P_U("body part", SMGI_SEC_JNTS, 4, smgi_joint, body_part, 3,
          SMG_ERROR_BLOB_VALUE, "JNTS[4].body_part"),
      P_U("mirror range", SMGI_SEC_JNTS, 2, smgi_joint, mirror, 31,
          SMG_ERROR_BLOB_INDEX, "JNTS[2].mirror"),
      P_U("mirror not mutual", SMGI_SEC_JNTS, 2, smgi_joint, mirror, 3,
          SMG_ERROR_BLOB_INDEX, "mirror"),
      P_F("offset inf", SMGI_SEC_JNTS, 4, smgi_joint, offset[1], inf,
          SMG_ERROR_BLOB_VALUE, "JNTS[4].offset"),
      P_F("mass ratio 2", SMGI_SEC_JNTS, 4, smgi_joint, mass_ratio, 2,
          SMG_ERROR_BLOB_VALUE, "JNTS[4].mass_ratio"),
      P_F("mass ratio nan", SMGI_SEC_JNTS, 4, smgi_joint, mass_ratio, nan,
          SMG_ERROR_BLOB_VALUE, "JNTS[4].mass_ratio"),
      /* STYL / ACTN */
      P_U("style name", SMGI_SEC_STYL, 1, smgi_label, name, 0xffffffffu,
          SMG_ERROR_BLOB_INDEX, "STYL[1].name"),
      P_U("action name", SMGI_SEC_ACTN, 1, smgi_label, name, strs + 100,
          SMG_ERROR_BLOB_INDEX, "ACTN[1].name"),
      P_U("action 0 not none", SMGI_SEC_ACTN, 0, smgi_label, name,
          punch_name, SMG_ERROR_BLOB_VALUE, "ACTN[0]"),
      /* CLIP */
      P_U("clip name", SMGI_SEC_CLIP, 2, smgi_clip, name, strs,
          SMG_ERROR_BLOB_INDEX, "CLIP[2].name"),
      P_U("clip frames", SMGI_SEC_CLIP, 3, smgi_clip, first_frame, 150,
          SMG_ERROR_BLOB_INDEX, "CLIP[3]"),
      P_U("clip frames overflow", SMGI_SEC_CLIP, 3, smgi_clip, frame_count,
          0xfffffff0u, SMG_ERROR_BLOB_INDEX, "CLIP[3]"),
      P_U("clip style", SMGI_SEC_CLIP, 3, smgi_clip, label, 2,
          SMG_ERROR_BLOB_INDEX, "CLIP[3].label"),
      P_U("clip action", SMGI_SEC_CLIP, 6, smgi_clip, label, 2,
          SMG_ERROR_BLOB_INDEX, "CLIP[6].label"),
      P_U("clip source", SMGI_SEC_CLIP, 0, smgi_clip, source_clip, 7,
          SMG_ERROR_BLOB_INDEX, "CLIP[0].source_clip"),
      /* POSE */
      {"pose root nan", SMGI_SEC_POSE, 5, 4, F32, 0, nan,
       SMG_ERROR_BLOB_VALUE, "POSE[5]"},
      {"pose root x inf", SMGI_SEC_POSE, 159, 0, F32, 0, inf,
       SMG_ERROR_BLOB_VALUE, "POSE[159] root"},
      /* FRMI */
      P_U("frame clip", SMGI_SEC_FRMI, 10, smgi_frame, clip, 7,
          SMG_ERROR_BLOB_INDEX, "FRMI[10].clip"),
      P_F("frame root2d", SMGI_SEC_FRMI, 10, smgi_frame, root2d[2], inf,
          SMG_ERROR_BLOB_VALUE, "FRMI[10].root2d"),
      P_F("frame phase", SMGI_SEC_FRMI, 11, smgi_frame, phase, nan,
          SMG_ERROR_BLOB_VALUE, "FRMI[11].phase"),
      /* finite but absurd magnitudes (a 1e30 rad heading once hung the
       * runtime's angle wrapping: found by make test-fuzz) */
      P_F("frame heading huge", SMGI_SEC_FRMI, 12, smgi_frame, root2d[2],
          -1.4e31f, SMG_ERROR_BLOB_VALUE, "FRMI[12].root2d"),
      P_F("frame x huge", SMGI_SEC_FRMI, 12, smgi_frame, root2d[0], 2e5f,
          SMG_ERROR_BLOB_VALUE, "FRMI[12].root2d"),
      {"pose root huge", SMGI_SEC_POSE, 6, 8, F32, 0, 3e5f,
       SMG_ERROR_BLOB_VALUE, "POSE[6] root"},
      P_F("joint offset huge", SMGI_SEC_JNTS, 6, smgi_joint, offset[0], 5e3f,
          SMG_ERROR_BLOB_VALUE, "JNTS[6].offset"),
      P_F("edge dheading huge", SMGI_SEC_LEDG, 1, smgi_edge,
          displacement[2], 1e20f, SMG_ERROR_BLOB_VALUE,
          "LEDG[1].displacement"),
      P_F("edge arc huge", SMGI_SEC_UEDG, 1, smgi_edge, arc_length, 1e9f,
          SMG_ERROR_BLOB_VALUE, "UEDG[1].arc_length"),
      P_F("ground height huge", SMGI_SEC_INFO, 0, smgi_info, ground_height,
          -1e6f, SMG_ERROR_BLOB_VALUE, "ground_height"),
      /* LNOD / LEDG */
      P_U("node frame", SMGI_SEC_LNOD, 1, smgi_node, frame, FIXTURE_FRAMES,
          SMG_ERROR_BLOB_INDEX, "LNOD[1].frame"),
      P_U("node first_edge", SMGI_SEC_LNOD, 1, smgi_node, first_edge, 3,
          SMG_ERROR_BLOB_INDEX, "LNOD[1].first_edge"),
      P_U("node edge_count", SMGI_SEC_LNOD, 1, smgi_node, edge_count, 3,
          SMG_ERROR_BLOB_INDEX, "LNOD[1]"),
      P_U("node edge_count short", SMGI_SEC_LNOD, 1, smgi_node, edge_count, 1,
          SMG_ERROR_BLOB_INDEX, "LNOD"),
      P_U("node edge_count huge", SMGI_SEC_LNOD, 0, smgi_node, edge_count,
          0xffffffffu, SMG_ERROR_BLOB_INDEX, "LNOD[0]"),
      P_U("node label", SMGI_SEC_LNOD, 0, smgi_node, label, 2,
          SMG_ERROR_BLOB_INDEX, "LNOD[0].label"),
      P_U("edge from", SMGI_SEC_LEDG, 1, smgi_edge, from, 1,
          SMG_ERROR_BLOB_INDEX, "LEDG[1].from"),
      P_U("edge to", SMGI_SEC_LEDG, 2, smgi_edge, to, 2,
          SMG_ERROR_BLOB_INDEX, "LEDG[2].to"),
      P_U("edge frames", SMGI_SEC_LEDG, 1, smgi_edge, first_frame, 150,
          SMG_ERROR_BLOB_INDEX, "LEDG[1]"),
      P_U("edge frames overflow", SMGI_SEC_LEDG, 1, smgi_edge, first_frame,
          0xffffffffu, SMG_ERROR_BLOB_INDEX, "LEDG[1]"),
      P_U("edge no frames", SMGI_SEC_LEDG, 0, smgi_edge, frame_count, 0,
          SMG_ERROR_BLOB_VALUE, "LEDG[0].frame_count"),
      P_F("edge displacement", SMGI_SEC_LEDG, 3, smgi_edge, displacement[2],
          nan, SMG_ERROR_BLOB_VALUE, "LEDG[3].displacement"),
      P_F("edge arc", SMGI_SEC_LEDG, 3, smgi_edge, arc_length, -1,
          SMG_ERROR_BLOB_VALUE, "LEDG[3].arc_length"),
      P_F("edge cost", SMGI_SEC_LEDG, 4, smgi_edge, cost, inf,
          SMG_ERROR_BLOB_VALUE, "LEDG[4].cost"),
      P_U("edge label", SMGI_SEC_LEDG, 5, smgi_edge, label, 2,
          SMG_ERROR_BLOB_INDEX, "LEDG[5].label"),
      /* UNOD / UEDG */
      P_U("upper node frame", SMGI_SEC_UNOD, 1, smgi_node, frame, 1000,
          SMG_ERROR_BLOB_INDEX, "UNOD[1].frame"),
      P_U("upper node label", SMGI_SEC_UNOD, 0, smgi_node, label, 2,
          SMG_ERROR_BLOB_INDEX, "UNOD[0].label"),
      P_U("upper edge to", SMGI_SEC_UEDG, 0, smgi_edge, to, 9,
          SMG_ERROR_BLOB_INDEX, "UEDG[0].to"),
      P_U("upper edge from", SMGI_SEC_UEDG, 1, smgi_edge, from, 0,
          SMG_ERROR_BLOB_INDEX, "UEDG[1].from"),
      P_U("upper edge frames", SMGI_SEC_UEDG, 1, smgi_edge, frame_count, 16,
          SMG_ERROR_BLOB_INDEX, "UEDG[1]"),
      /* SPLC */
      P_U("splice frame", SMGI_SEC_SPLC, 1, smgi_splice, lower_frame,
          FIXTURE_FRAMES, SMG_ERROR_BLOB_INDEX, "SPLC[1].lower_frame"),
      P_U("splice action", SMGI_SEC_SPLC, 1, smgi_splice, action, 2,
          SMG_ERROR_BLOB_INDEX, "SPLC[1].action"),
      P_U("splice edge", SMGI_SEC_SPLC, 2, smgi_splice, upper_edge, 2,
          SMG_ERROR_BLOB_INDEX, "SPLC[2].upper_edge"),
      P_U("splice offset", SMGI_SEC_SPLC, 2, smgi_splice, upper_offset, 15,
          SMG_ERROR_BLOB_INDEX, "SPLC[2].upper_offset"),
      P_F("splice distance", SMGI_SEC_SPLC, 0, smgi_splice, distance, nan,
          SMG_ERROR_BLOB_VALUE, "SPLC[0].distance"),
      P_F("splice correction", SMGI_SEC_SPLC, 0, smgi_splice, correction[3],
          0, SMG_ERROR_BLOB_VALUE, "SPLC[0].correction"),
  };
  size_t i;
  for (i = 0; i < sizeof plants / sizeof plants[0]; ++i) {
    const plant* p = &plants[i];
    unsigned char* c = test_aligned_copy(f->blob, f->size);
    smgi_graph_data v;
    char err[256];
    smg_result r;
    smg_graph* g = NULL;
    if (p->tag == SMGI_SEC_STRS) {
      /* one byte, not a 4-byte field */
      c[test_section(c, SMGI_SEC_STRS)->offset + p->record] = 'x';
    } else {
      apply_plant(c, p);
    }
    /* unsealed: the checksum catches it first */
    assert_int_equal(smgi_blob_read(c, f->size, 0, &v, NULL, 0),
                     SMG_ERROR_BLOB_CHECKSUM);
    /* skipping the checksum: the structural check still catches it */
    r = smgi_blob_read(c, f->size, SMG_GRAPH_SKIP_CHECKSUM, &v, err,
                       sizeof err);
    if (r != p->expect || !strstr(err, p->needle))
      fail_msg("plant '%s': expected %s mentioning '%s', got %s: '%s'",
               p->what, smg_result_string(p->expect), p->needle,
               smg_result_string(r), err);
    /* re-sealed: same result with full validation and through the API */
    test_reseal(c);
    assert_int_equal(smgi_blob_read(c, f->size, 0, &v, NULL, 0), p->expect);
    assert_int_equal(smg_graph_load_memory(c, f->size, NULL, &g), p->expect);
    assert_null(g);
    free(c);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_checksum_known_values),
      cmocka_unit_test(test_checksum_detects_flips),
      cmocka_unit_test(test_checksum_in_pieces),
      cmocka_unit_test_setup_teardown(test_first_bad_frame_is_reported, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_write_is_deterministic_and_aligned,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_round_trip, setup, teardown),
      cmocka_unit_test_setup_teardown(
          test_write_uses_allocator_and_reports_oom, setup, teardown),
      cmocka_unit_test_setup_teardown(test_write_rejects_bad_arguments, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_write_validates_its_output, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_empty_graphs, setup, teardown),
      cmocka_unit_test_setup_teardown(test_read_rejects_bad_arguments, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_misaligned_memory, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_every_truncation_fails, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(
          test_truncation_with_patched_header_fails, setup, teardown),
      cmocka_unit_test_setup_teardown(test_header_bit_flips, setup, teardown),
      cmocka_unit_test_setup_teardown(test_payload_bit_flips_fail_checksum,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_table_bit_flips_without_checksum,
                                      setup, teardown),
      cmocka_unit_test_setup_teardown(test_header_fields, setup, teardown),
      cmocka_unit_test_setup_teardown(test_version_1_is_refused, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_any_rotation_bits_load, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_table_entries, setup, teardown),
      cmocka_unit_test_setup_teardown(test_unknown_section_is_ignored, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_planted_values, setup, teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
