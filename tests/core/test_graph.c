/*
 * test_graph.c - the public smg_graph_* API: loading from memory (in
 * place) and from files, inspection, descriptors, allocator and logger
 * hooks, the lifetime rule, and NULL/misuse arguments on every function.
 */
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "blob_testutil.h"
#include "fixture_graph.h"
#include "graph_data.h"
#include "smg.h"

typedef struct fx {
  unsigned char* blob;
  size_t size;
  char path[64];
} fx;

static int setup(void** state) {
  fx* f = (fx*)calloc(1, sizeof *f);
  void* data = NULL;
  if (!f || fixture_graph_blob(&data, &f->size) != SMG_OK) return -1;
  f->blob = (unsigned char*)data;
  f->path[0] = '\0';
  *state = f;
  return 0;
}

static int teardown(void** state) {
  fx* f = (fx*)*state;
  if (f->path[0]) unlink(f->path);
  smgi_blob_free(f->blob, NULL);
  free(f);
  return 0;
}

/* Write `size` bytes to a fresh temp file; its name goes to f->path. */
static void write_temp(fx* f, const void* data, size_t size) {
  int fd;
  FILE* fp;
  strcpy(f->path, "/tmp/smg_test_graph_XXXXXX");
  fd = mkstemp(f->path);
  assert_true(fd >= 0);
  fp = fdopen(fd, "wb");
  assert_non_null(fp);
  assert_int_equal(fwrite(data, 1, size, fp), size);
  assert_int_equal(fclose(fp), 0);
}

static void check_info(const smg_graph* g, size_t blob_size) {
  smg_graph_info info;
  memset(&info, 0xab, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  assert_int_equal(info.struct_size, sizeof info);
  assert_int_equal(info.format_version, SMGI_BLOB_VERSION);
  assert_int_equal(info.joint_count, FIXTURE_JOINTS);
  assert_int_equal(info.style_count, 2);
  assert_int_equal(info.action_count, 2);
  assert_int_equal(info.frame_count, FIXTURE_FRAMES);
  assert_int_equal(info.lower_node_count, FIXTURE_LOWER_NODES);
  assert_int_equal(info.lower_edge_count, FIXTURE_LOWER_EDGES);
  assert_int_equal(info.upper_node_count, FIXTURE_UPPER_NODES);
  assert_int_equal(info.upper_edge_count, FIXTURE_UPPER_EDGES);
  assert_int_equal(info.splice_count, FIXTURE_SPLICES);
  assert_int_equal(info.character_count, 0);
  assert_true(info.frame_rate == FIXTURE_FPS);
  assert_true(info.reserved0 == 0.0f);
  assert_int_equal(info.blob_size, blob_size);
}

static void test_load_memory_in_place(void** state) {
  fx* f = (fx*)*state;
  smg_graph* g = NULL;
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, NULL, &g), SMG_OK);
  assert_non_null(g);
  check_info(g, f->size);
  /* no copy: the graph reads the caller's bytes */
  assert_true((const unsigned char*)g->data.info >= f->blob &&
              (const unsigned char*)g->data.info < f->blob + f->size);
  assert_null(g->owned_blob);
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
}

static void test_load_file(void** state) {
  fx* f = (fx*)*state;
  smg_graph* g = NULL;
  write_temp(f, f->blob, f->size);
  assert_int_equal(smg_graph_load_file(f->path, NULL, &g), SMG_OK);
  assert_non_null(g);
  check_info(g, f->size);
  assert_non_null(g->owned_blob);
  assert_int_equal((uintptr_t)g->owned_blob % 16, 0);
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
}

static void test_load_file_errors(void** state) {
  fx* f = (fx*)*state;
  smg_graph* g = NULL;
  unsigned char* bad;
  assert_int_equal(
      smg_graph_load_file("/nonexistent/dir/graph.smg", NULL, &g),
      SMG_ERROR_IO);
  assert_int_equal(smg_graph_load_file("/tmp", NULL, &g), SMG_ERROR_IO);
  assert_int_equal(smg_graph_load_file("", NULL, &g), SMG_ERROR_IO);
  assert_null(g);
  /* empty file: read fine, then rejected as a blob */
  write_temp(f, "", 0);
  assert_int_equal(smg_graph_load_file(f->path, NULL, &g),
                   SMG_ERROR_BLOB_TRUNCATED);
  unlink(f->path);
  /* corrupted file */
  bad = test_aligned_copy(f->blob, f->size);
  bad[f->size / 2] ^= 0x10;
  write_temp(f, bad, f->size);
  free(bad);
  assert_int_equal(smg_graph_load_file(f->path, NULL, &g),
                   SMG_ERROR_BLOB_CHECKSUM);
  assert_null(g);
  unlink(f->path);
  /* truncated file */
  write_temp(f, f->blob, f->size - 32);
  assert_int_equal(smg_graph_load_file(f->path, NULL, &g),
                   SMG_ERROR_BLOB_TRUNCATED);
  assert_null(g);
}

static void test_joints(void** state) {
  fx* f = (fx*)*state;
  smg_graph* g = NULL;
  smg_joint_info j;
  uint32_t idx = 99;
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, NULL, &g), SMG_OK);
  memset(&j, 0, sizeof j);
  j.struct_size = sizeof j;
  assert_int_equal(smg_graph_get_joint(g, 0, &j), SMG_OK);
  assert_string_equal(j.name, "Hips");
  assert_int_equal(j.parent, SMG_NO_PARENT);
  assert_int_equal(j.body_part, SMG_BODY_ROOT);
  assert_int_equal(smg_graph_get_joint(g, 4, &j), SMG_OK);
  assert_string_equal(j.name, "LeftFoot");
  assert_int_equal(j.parent, 3);
  assert_int_equal(j.body_part, SMG_BODY_LOWER);
  assert_true(j.rest_offset[1] < -0.3f && j.rest_offset[1] > -0.5f);
  assert_int_equal(smg_graph_get_joint(g, 30, &j), SMG_OK);
  assert_string_equal(j.name, "RThumb");
  assert_int_equal(j.body_part, SMG_BODY_UPPER);
  assert_int_equal(smg_graph_get_joint(g, 31, &j), SMG_ERROR_OUT_OF_RANGE);
  assert_int_equal(smg_graph_get_joint(g, 0xffffffffu, &j),
                   SMG_ERROR_OUT_OF_RANGE);
  assert_int_equal(smg_graph_find_joint(g, "LeftFoot", &idx), SMG_OK);
  assert_int_equal(idx, 4);
  assert_int_equal(smg_graph_find_joint(g, "RThumb", &idx), SMG_OK);
  assert_int_equal(idx, 30);
  idx = 77;
  assert_int_equal(smg_graph_find_joint(g, "Tail", &idx),
                   SMG_ERROR_NOT_FOUND);
  assert_int_equal(smg_graph_find_joint(g, "", &idx), SMG_ERROR_NOT_FOUND);
  assert_int_equal(idx, 77); /* outputs untouched on failure */
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
}

static void test_styles_and_actions(void** state) {
  fx* f = (fx*)*state;
  smg_graph* g = NULL;
  const char* name = NULL;
  uint32_t i = 99;
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, NULL, &g), SMG_OK);
  assert_int_equal(smg_graph_get_style_name(g, 0, &name), SMG_OK);
  assert_string_equal(name, "walk");
  assert_int_equal(smg_graph_get_style_name(g, 1, &name), SMG_OK);
  assert_string_equal(name, "run");
  assert_int_equal(smg_graph_get_style_name(g, 2, &name),
                   SMG_ERROR_UNKNOWN_STYLE);
  assert_int_equal(smg_graph_get_action_name(g, 0, &name), SMG_OK);
  assert_string_equal(name, "none");
  assert_int_equal(smg_graph_get_action_name(g, 1, &name), SMG_OK);
  assert_string_equal(name, "punch");
  assert_int_equal(smg_graph_get_action_name(g, 2, &name),
                   SMG_ERROR_UNKNOWN_ACTION);
  assert_int_equal(smg_graph_find_style(g, "run", &i), SMG_OK);
  assert_int_equal(i, 1);
  assert_int_equal(smg_graph_find_style(g, "punch", &i),
                   SMG_ERROR_UNKNOWN_STYLE);
  assert_int_equal(smg_graph_find_action(g, "punch", &i), SMG_OK);
  assert_int_equal(i, 1);
  assert_int_equal(smg_graph_find_action(g, "none", &i), SMG_OK);
  assert_int_equal(i, 0);
  assert_int_equal(smg_graph_find_action(g, "walk", &i),
                   SMG_ERROR_UNKNOWN_ACTION);
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
}

/* Older (smaller) output structs get only their prefix written. */
static void test_struct_size_rules(void** state) {
  fx* f = (fx*)*state;
  smg_graph* g = NULL;
  smg_graph_info info;
  smg_joint_info j;
  smg_graph_desc desc;
  const uint32_t small = (uint32_t)offsetof(smg_graph_info, frame_count);
  size_t i;
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, NULL, &g), SMG_OK);
  memset(&info, 0xcd, sizeof info);
  info.struct_size = small;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  assert_int_equal(info.joint_count, FIXTURE_JOINTS);
  assert_int_equal(info.action_count, 2);
  for (i = small; i < sizeof info; ++i)
    assert_int_equal(((unsigned char*)&info)[i], 0xcd);
  info.struct_size = 0;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_ERROR_INVALID_ARGUMENT);
  info.struct_size = sizeof info + 4;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_ERROR_INVALID_ARGUMENT);
  memset(&j, 0, sizeof j);
  j.struct_size = 2;
  assert_int_equal(smg_graph_get_joint(g, 0, &j), SMG_ERROR_INVALID_ARGUMENT);
  j.struct_size = sizeof j + 1;
  assert_int_equal(smg_graph_get_joint(g, 0, &j), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_destroy(g), SMG_OK);

  /* descriptors: 0 / too big / unknown flags rejected, older size and the
   * SKIP_CHECKSUM flag accepted */
  g = NULL;
  memset(&desc, 0, sizeof desc);
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, &desc, &g),
                   SMG_ERROR_INVALID_ARGUMENT);
  desc.struct_size = sizeof desc + 8;
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, &desc, &g),
                   SMG_ERROR_INVALID_ARGUMENT);
  desc.struct_size = sizeof desc;
  desc.flags = 0x100;
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, &desc, &g),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_load_file("/nonexistent", &desc, &g),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_null(g);
  desc.flags = SMG_GRAPH_SKIP_CHECKSUM;
  desc.struct_size = (uint32_t)offsetof(smg_graph_desc, allocator);
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, &desc, &g),
                   SMG_OK);
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
}

typedef struct counting_alloc {
  int allocs, frees, fail_at;
  size_t live;
} counting_alloc;

static void* count_alloc(size_t size, size_t align, void* user) {
  counting_alloc* c = (counting_alloc*)user;
  void* p = NULL;
  if (c->fail_at >= 0 && c->allocs >= c->fail_at) return NULL;
  if (posix_memalign(&p, align < sizeof(void*) ? sizeof(void*) : align,
                     size) != 0)
    return NULL;
  c->allocs++;
  return p;
}

static void count_free(void* p, void* user) {
  counting_alloc* c = (counting_alloc*)user;
  c->frees++;
  free(p);
}

/* Memory goes through the hooks; every allocation failure point fails the
 * load cleanly with OUT_OF_MEMORY and frees what was taken. */
static void test_allocator_hooks_and_oom(void** state) {
  fx* f = (fx*)*state;
  counting_alloc c;
  smg_graph_desc desc;
  smg_graph* g = NULL;
  int n, total;
  write_temp(f, f->blob, f->size);
  memset(&desc, 0, sizeof desc);
  desc.struct_size = sizeof desc;
  desc.allocator.alloc = count_alloc;
  desc.allocator.free = count_free;
  desc.allocator.user = &c;
  memset(&c, 0, sizeof c);
  c.fail_at = -1;
  assert_int_equal(smg_graph_load_file(f->path, &desc, &g), SMG_OK);
  total = c.allocs;
  assert_true(total >= 2); /* the blob buffer and the graph at least */
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
  assert_int_equal(c.frees, c.allocs);
  for (n = 0; n < total; ++n) {
    memset(&c, 0, sizeof c);
    c.fail_at = n;
    g = NULL;
    assert_int_equal(smg_graph_load_file(f->path, &desc, &g),
                     SMG_ERROR_OUT_OF_MEMORY);
    assert_null(g);
    assert_int_equal(c.frees, c.allocs);
  }
  /* in place: fewer allocations, same rule */
  memset(&c, 0, sizeof c);
  c.fail_at = 0;
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, &desc, &g),
                   SMG_ERROR_OUT_OF_MEMORY);
  assert_int_equal(c.frees, c.allocs);
  /* only one of alloc/free set */
  desc.allocator.free = NULL;
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, &desc, &g),
                   SMG_ERROR_INVALID_ARGUMENT);
}

/* An allocator that ignores the requested alignment is caught rather than
 * trusted. */
static void* misaligning_alloc(size_t size, size_t align, void* user) {
  unsigned char* p = (unsigned char*)malloc(size + 8);
  (void)align;
  (void)user;
  if (!p) return NULL;
  if ((uintptr_t)p % 16 == 0) {
    p[0] = 1; /* remember to undo the shift */
    return p + 8;
  }
  p[0] = 0;
  return p;
}
static void misaligning_free(void* ptr, void* user) {
  unsigned char* p = (unsigned char*)ptr;
  (void)user;
  if ((uintptr_t)p % 16 == 8) p -= 8;
  free(p);
}

static void test_misaligning_allocator_is_refused(void** state) {
  fx* f = (fx*)*state;
  smg_graph_desc desc;
  smg_graph* g = NULL;
  smg_result r;
  write_temp(f, f->blob, f->size);
  memset(&desc, 0, sizeof desc);
  desc.struct_size = sizeof desc;
  desc.allocator.alloc = misaligning_alloc;
  desc.allocator.free = misaligning_free;
  r = smg_graph_load_file(f->path, &desc, &g);
  /* malloc's 16-byte alignment means every block comes back misaligned */
  assert_int_equal(r, SMG_ERROR_OUT_OF_MEMORY);
  assert_null(g);
}

typedef struct log_capture {
  int calls;
  uint32_t level;
  char last[512];
} log_capture;

static void capture_log(uint32_t level, const char* message, void* user) {
  log_capture* l = (log_capture*)user;
  l->calls++;
  l->level = level;
  snprintf(l->last, sizeof l->last, "%s", message);
}

static void test_logger_explains_rejection(void** state) {
  fx* f = (fx*)*state;
  log_capture log;
  smg_graph_desc desc;
  smg_graph* g = NULL;
  unsigned char* c = test_aligned_copy(f->blob, f->size);
  smgi_edge* edges = (smgi_edge*)test_section_data(c, SMGI_SEC_LEDG);
  edges[3].to = 42;
  test_reseal(c);
  memset(&log, 0, sizeof log);
  memset(&desc, 0, sizeof desc);
  desc.struct_size = sizeof desc;
  desc.logger.func = capture_log;
  desc.logger.user = &log;
  assert_int_equal(smg_graph_load_memory(c, f->size, &desc, &g),
                   SMG_ERROR_BLOB_INDEX);
  assert_int_equal(log.calls, 1);
  assert_int_equal(log.level, SMG_LOG_ERROR);
  assert_non_null(strstr(log.last, "LEDG[3].to"));
  assert_non_null(strstr(log.last, "SMG_ERROR_BLOB_INDEX"));
  assert_null(strchr(log.last, '\n'));
  log.calls = 0;
  assert_int_equal(smg_graph_load_file("/nonexistent.smg", &desc, &g),
                   SMG_ERROR_IO);
  assert_int_equal(log.calls, 1);
  assert_non_null(strstr(log.last, "/nonexistent.smg"));
  free(c);
}

/* The lifetime rule: no destroy while characters hold the graph. */
static void test_destroy_in_use(void** state) {
  fx* f = (fx*)*state;
  smg_graph* g = NULL;
  smg_graph_info info;
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, NULL, &g), SMG_OK);
  smgi_graph_retain(g);
  smgi_graph_retain(g);
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  assert_int_equal(info.character_count, 2);
  assert_int_equal(smg_graph_destroy(g), SMG_ERROR_IN_USE);
  smgi_graph_release(g);
  assert_int_equal(smg_graph_destroy(g), SMG_ERROR_IN_USE);
  smgi_graph_release(g);
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
}

/* Characters on several threads retain/release one graph concurrently:
 * the count must come back exactly to zero. */
static void* retain_release_many(void* arg) {
  smg_graph* g = (smg_graph*)arg;
  int i;
  for (i = 0; i < 20000; ++i) {
    smgi_graph_retain(g);
    smgi_graph_release(g);
  }
  return NULL;
}

static void test_retain_release_is_atomic(void** state) {
  fx* f = (fx*)*state;
  smg_graph* g = NULL;
  pthread_t th[4];
  int i;
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, NULL, &g), SMG_OK);
  smgi_graph_retain(g); /* held across the race */
  for (i = 0; i < 4; ++i)
    assert_int_equal(pthread_create(&th[i], NULL, retain_release_many, g), 0);
  for (i = 0; i < 4; ++i) assert_int_equal(pthread_join(th[i], NULL), 0);
  assert_int_equal(smg_graph_destroy(g), SMG_ERROR_IN_USE);
  smgi_graph_release(g);
  assert_int_equal(g->character_count, 0);
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
}

/* The blob `make` bakes from the synthetic clips loads and has the shape
 * the rest of the project expects (skipped when it was not built). */
static void test_default_blob_loads(void** state) {
  char path[1024];
  smg_graph* g = NULL;
  smg_graph_info info;
  const char* name = NULL;
  FILE* probe;
  (void)state;
  snprintf(path, sizeof path, "%s/default.smg", SMG_BUILD_DIR);
  probe = fopen(path, "rb");
  if (!probe) {
    printf("skipped: %s not built (run make first)\n", path);
    skip();
  }
  fclose(probe);
  assert_int_equal(smg_graph_load_file(path, NULL, &g), SMG_OK);
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  assert_int_equal(smg_graph_get_info(g, &info), SMG_OK);
  assert_int_equal(info.format_version, SMGI_BLOB_VERSION);
  assert_int_equal(info.joint_count, 31);
  assert_true(info.style_count >= 1);
  assert_true(info.action_count >= 1);
  assert_true(info.lower_node_count >= 1 && info.lower_edge_count >= 1);
  assert_int_equal(smg_graph_get_action_name(g, 0, &name), SMG_OK);
  assert_string_equal(name, "none");
  assert_int_equal(smg_graph_destroy(g), SMG_OK);
}

/* Two graphs from one blob are independent. */
static void test_two_graphs_share_a_blob(void** state) {
  fx* f = (fx*)*state;
  smg_graph *a = NULL, *b = NULL;
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, NULL, &a), SMG_OK);
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, NULL, &b), SMG_OK);
  assert_true(a != b);
  assert_int_equal(smg_graph_destroy(a), SMG_OK);
  check_info(b, f->size);
  assert_int_equal(smg_graph_destroy(b), SMG_OK);
}

/* NULL and misuse on every smg_graph_* function. */
static void test_null_arguments(void** state) {
  fx* f = (fx*)*state;
  smg_graph* g = NULL;
  smg_graph* keep = NULL;
  smg_graph_info info;
  smg_joint_info j;
  const char* name = NULL;
  uint32_t idx = 0;
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, NULL, &keep),
                   SMG_OK);
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  memset(&j, 0, sizeof j);
  j.struct_size = sizeof j;

  assert_int_equal(smg_graph_load_file(NULL, NULL, &g),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_load_file("x.smg", NULL, NULL),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_load_memory(NULL, f->size, NULL, &g),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_load_memory(f->blob, f->size, NULL, NULL),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_load_memory(f->blob, 0, NULL, &g),
                   SMG_ERROR_BLOB_TRUNCATED);
  assert_int_equal(smg_graph_load_memory(f->blob + 16, f->size - 16, NULL,
                                         &g),
                   SMG_ERROR_BLOB_MAGIC);
  assert_int_equal(smg_graph_load_memory(f->blob + 1, f->size - 1, NULL, &g),
                   SMG_ERROR_BLOB_ALIGNMENT);
  assert_null(g);
  assert_int_equal(smg_graph_destroy(NULL), SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_get_info(NULL, &info),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_get_info(keep, NULL),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_get_joint(NULL, 0, &j),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_get_joint(keep, 0, NULL),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_find_joint(NULL, "Hips", &idx),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_find_joint(keep, NULL, &idx),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_find_joint(keep, "Hips", NULL),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_get_style_name(NULL, 0, &name),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_get_style_name(keep, 0, NULL),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_find_style(NULL, "walk", &idx),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_find_style(keep, NULL, &idx),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_find_style(keep, "walk", NULL),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_get_action_name(NULL, 0, &name),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_get_action_name(keep, 0, NULL),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_find_action(NULL, "none", &idx),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_find_action(keep, NULL, &idx),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smg_graph_find_action(keep, "none", NULL),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_null(name);
  assert_int_equal(smg_graph_destroy(keep), SMG_OK);
}

int main(void) {
#define T(fn) cmocka_unit_test_setup_teardown(fn, setup, teardown)
  const struct CMUnitTest tests[] = {
      T(test_load_memory_in_place),
      T(test_load_file),
      T(test_load_file_errors),
      T(test_joints),
      T(test_styles_and_actions),
      T(test_struct_size_rules),
      T(test_allocator_hooks_and_oom),
      T(test_misaligning_allocator_is_refused),
      T(test_logger_explains_rejection),
      T(test_destroy_in_use),
      T(test_two_graphs_share_a_blob),
      T(test_retain_release_is_atomic),
      T(test_default_blob_loads),
      T(test_null_arguments),
  };
#undef T
  return cmocka_run_group_tests(tests, NULL, NULL);
}
