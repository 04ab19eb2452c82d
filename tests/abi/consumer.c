/*
 * consumer.c - a tiny program built against an *installed* libsmg through
 * pkg-config (make test-install): proves the header, the pkg-config file
 * and the shared library's soname all work from outside the tree.
 */
#include <smg.h>
#include <stdio.h>
#include <string.h>

int main(void) {
  static const unsigned char not_a_blob[64] __attribute__((aligned(16))) = {
      'N', 'O', 'T', 'A', 'B', 'L', 'O', 'B'};
  smg_graph* g = NULL;
  smg_result r;
  if (smg_version() != (uint32_t)SMG_VERSION) {
    fprintf(stderr, "consumer: header/library version mismatch\n");
    return 1;
  }
  r = smg_graph_load_memory(not_a_blob, sizeof not_a_blob, NULL, &g);
  if (r != SMG_ERROR_BLOB_MAGIC || g != NULL) {
    fprintf(stderr, "consumer: expected SMG_ERROR_BLOB_MAGIC, got %s\n",
            smg_result_string(r));
    return 1;
  }
  printf("consumer: libsmg %u.%u.%u works (%s)\n", SMG_VERSION_MAJOR,
         SMG_VERSION_MINOR, SMG_VERSION_PATCH, smg_result_string(r));
  return 0;
}
