/*
 * blob_write.c - deterministic graph-blob writer (docs/blob-format.md).
 *
 * Sections are laid out in one fixed order, each 16-byte aligned, with all
 * padding zeroed, so the same smgi_graph_data always gives the same bytes
 * (baked files can be compared and cached by hash). The result is run
 * through smgi_blob_read before it is returned: the writer can never hand
 * out a blob the runtime would reject.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "blob.h"

typedef struct out_section {
  uint32_t tag;
  const void* data;
  uint32_t count;
  uint32_t record_size;
} out_section;

static uint64_t align_up(uint64_t v) {
  return (v + (SMGI_BLOB_ALIGN - 1)) & ~(uint64_t)(SMGI_BLOB_ALIGN - 1);
}

static smg_result write_fail(char* error, size_t error_size, smg_result code,
                             const char* what) {
  if (error && error_size > 0) snprintf(error, error_size, "%s", what);
  return code;
}

smg_result smgi_blob_write(const smgi_graph_data* g,
                           const smg_allocator* allocator, void** out_data,
                           size_t* out_size, char* error, size_t error_size) {
  smg_allocator a;
  out_section secs[13];
  smgi_blob_header h;
  smgi_graph_data check;
  unsigned char* buf;
  uint64_t offset, total, pose_record;
  uint32_t i, n = 0;
  smg_result res;

  if (error && error_size > 0) error[0] = '\0';
  if (!g || !out_data || !out_size)
    return write_fail(error, error_size, SMG_ERROR_INVALID_ARGUMENT,
                      "smgi_blob_write: graph, out_data and out_size are "
                      "required");
  if (smgi_allocator_resolve(allocator, &a) != SMG_OK)
    return write_fail(error, error_size, SMG_ERROR_INVALID_ARGUMENT,
                      "smgi_blob_write: allocator needs both alloc and free");
  if (!g->info)
    return write_fail(error, error_size, SMG_ERROR_INVALID_ARGUMENT,
                      "smgi_blob_write: graph->info is NULL");
  /* SMGI_POSE_RECORD_SIZE in 64 bits; g->poses already holds packed
   * records (smgi_pose_pack) */
  pose_record = (12u + 6u * (uint64_t)g->joint_count + 3u) & ~(uint64_t)3u;
  if (pose_record > UINT32_MAX)
    return write_fail(error, error_size, SMG_ERROR_INVALID_ARGUMENT,
                      "smgi_blob_write: joint_count too large");

#define ADD(t, p, c, rs)                                                  \
  do {                                                                    \
    if ((c) > 0 && !(p))                                                  \
      return write_fail(error, error_size, SMG_ERROR_INVALID_ARGUMENT,    \
                        "smgi_blob_write: NULL array with nonzero count " \
                        "for section " #t);                               \
    secs[n].tag = (t);                                                    \
    secs[n].data = (p);                                                   \
    secs[n].count = (c);                                                  \
    secs[n].record_size = (uint32_t)(rs);                                 \
    ++n;                                                                  \
  } while (0)
  ADD(SMGI_SEC_INFO, g->info, 1u, sizeof(smgi_info));
  ADD(SMGI_SEC_STRS, g->strings, g->strings_size, 1u);
  ADD(SMGI_SEC_JNTS, g->joints, g->joint_count, sizeof(smgi_joint));
  ADD(SMGI_SEC_STYL, g->styles, g->style_count, sizeof(smgi_label));
  ADD(SMGI_SEC_ACTN, g->actions, g->action_count, sizeof(smgi_label));
  ADD(SMGI_SEC_CLIP, g->clips, g->clip_count, sizeof(smgi_clip));
  ADD(SMGI_SEC_POSE, g->poses, g->frame_count, pose_record);
  ADD(SMGI_SEC_FRMI, g->frames, g->frame_count, sizeof(smgi_frame));
  ADD(SMGI_SEC_LNOD, g->lower_nodes, g->lower_node_count, sizeof(smgi_node));
  ADD(SMGI_SEC_LEDG, g->lower_edges, g->lower_edge_count, sizeof(smgi_edge));
  ADD(SMGI_SEC_UNOD, g->upper_nodes, g->upper_node_count, sizeof(smgi_node));
  ADD(SMGI_SEC_UEDG, g->upper_edges, g->upper_edge_count, sizeof(smgi_edge));
  ADD(SMGI_SEC_SPLC, g->splices, g->splice_count, sizeof(smgi_splice));
#undef ADD

  /* Layout pass: header, table, then the sections in order. */
  offset = align_up(sizeof(smgi_blob_header) +
                    (uint64_t)n * sizeof(smgi_blob_section));
  for (i = 0; i < n; ++i)
    offset = align_up(offset + (uint64_t)secs[i].count * secs[i].record_size);
  total = offset;
  if (total > (uint64_t)SIZE_MAX)
    return write_fail(error, error_size, SMG_ERROR_OUT_OF_MEMORY,
                      "smgi_blob_write: blob larger than the address space");

  buf = (unsigned char*)smgi_alloc(&a, (size_t)total, SMGI_BLOB_ALIGN);
  if (!buf)
    return write_fail(error, error_size, SMG_ERROR_OUT_OF_MEMORY,
                      "smgi_blob_write: out of memory");
  memset(buf, 0, (size_t)total);

  offset = align_up(sizeof(smgi_blob_header) +
                    (uint64_t)n * sizeof(smgi_blob_section));
  for (i = 0; i < n; ++i) {
    smgi_blob_section e;
    uint64_t bytes = (uint64_t)secs[i].count * secs[i].record_size;
    memset(&e, 0, sizeof e);
    e.tag = secs[i].tag;
    e.alignment = SMGI_BLOB_ALIGN;
    e.offset = offset;
    e.size = bytes;
    e.count = secs[i].count;
    e.record_size = secs[i].record_size;
    memcpy(buf + sizeof(smgi_blob_header) + i * sizeof e, &e, sizeof e);
    if (bytes > 0) memcpy(buf + offset, secs[i].data, (size_t)bytes);
    offset = align_up(offset + bytes);
  }

  memset(&h, 0, sizeof h);
  memcpy(h.magic, SMGI_BLOB_MAGIC, 8);
  h.endian = SMGI_BLOB_ENDIAN;
  h.version = SMGI_BLOB_VERSION;
  h.total_size = total;
  h.header_size = sizeof(smgi_blob_header);
  h.section_count = n;
  h.checksum = smgi_blob_checksum(buf + sizeof h, (size_t)(total - sizeof h));
  memcpy(buf, &h, sizeof h);

  res = smgi_blob_read(buf, (size_t)total, 0, &check, error, error_size);
  if (res != SMG_OK) {
    smgi_free(&a, buf);
    return res;
  }
  *out_data = buf;
  *out_size = (size_t)total;
  return SMG_OK;
}

void smgi_blob_free(void* data, const smg_allocator* allocator) {
  smg_allocator a;
  if (!data) return;
  if (smgi_allocator_resolve(allocator, &a) != SMG_OK) return;
  smgi_free(&a, data);
}
