/*
 * graph.c - loading, inspecting and destroying an smg_graph.
 *
 * A graph is a validated view into one blob (smgi_blob_read does all the
 * checking) plus the runtime's derived lookup tables. Loading from memory
 * uses the caller's bytes in place; loading from a file reads them once
 * into a 16-byte aligned buffer owned by the graph. Nothing here runs per
 * frame.
 */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "abi.h"
#include "alloc.h"
#include "blob.h"
#include "graph_data.h"
#include "log.h"

/* Files larger than this are refused before any allocation: a real baked
 * graph is a few MB, so 1 GiB means a wrong path, not a graph. */
#define SMGI_MAX_BLOB_FILE ((uint64_t)1 << 30)

/* Copy a caller descriptor of any older, smaller size into a full one
 * whose missing fields are zero (= defaults). */
static smg_result resolve_desc(const smg_graph_desc* in, smg_graph_desc* out,
                               smg_allocator* alloc) {
  memset(out, 0, sizeof *out);
  if (in) {
    if (!smgi_struct_size_ok(in->struct_size, sizeof *out))
      return SMG_ERROR_INVALID_ARGUMENT;
    memcpy(out, in, in->struct_size);
  }
  out->struct_size = sizeof *out;
  if (out->flags & ~(uint32_t)SMG_GRAPH_SKIP_CHECKSUM)
    return SMG_ERROR_INVALID_ARGUMENT;
  return smgi_allocator_resolve(&out->allocator, alloc);
}

/* Validate `data`, build the graph object around it. On success the graph
 * owns `owned` (may be NULL); on failure the caller still does. */
static smg_result make_graph(const void* data, size_t size, void* owned,
                             const smg_graph_desc* desc,
                             const smg_allocator* alloc,
                             smg_graph** out_graph) {
  char reason[256];
  smgi_graph_data view;
  smgi_blob_header header;
  smg_graph* g;
  smg_result res;

  res = smgi_blob_read(data, size, desc->flags, &view, reason, sizeof reason);
  if (res != SMG_OK) {
    smgi_log(&desc->logger, SMG_LOG_ERROR, "graph blob rejected (%s): %s",
             smg_result_string(res), reason);
    return res;
  }
  memcpy(&header, data, sizeof header); /* validated by smgi_blob_read */

  g = (smg_graph*)smgi_alloc(alloc, sizeof *g, 16);
  if (!g) {
    smgi_log(&desc->logger, SMG_LOG_ERROR, "out of memory for smg_graph");
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  memset(g, 0, sizeof *g);
  g->data = view;
  g->allocator = *alloc;
  g->logger = desc->logger;
  g->blob_size = size;
  g->format_version = header.version;
  g->character_count = 0;
  g->derived = NULL;

  res = smgi_graph_derived_build(g);
  if (res != SMG_OK) {
    smgi_log(&desc->logger, SMG_LOG_ERROR,
             "building runtime tables failed: %s", smg_result_string(res));
    smgi_graph_derived_free(g);
    smgi_free(alloc, g);
    return res;
  }
  g->owned_blob = owned;
  *out_graph = g;
  return SMG_OK;
}

smg_result smg_graph_load_memory(const void* data, size_t size,
                                 const smg_graph_desc* desc,
                                 smg_graph** out_graph) {
  smg_graph_desc d;
  smg_allocator alloc;
  smg_result res;
  if (!data || !out_graph) return SMG_ERROR_INVALID_ARGUMENT;
  if ((res = resolve_desc(desc, &d, &alloc)) != SMG_OK) return res;
  return make_graph(data, size, NULL, &d, &alloc, out_graph);
}

/* Read the whole regular file at `path` into an aligned buffer. */
static smg_result read_file(const char* path, const smg_graph_desc* desc,
                            const smg_allocator* alloc, void** out_buf,
                            size_t* out_size) {
  FILE* f;
  struct stat st;
  unsigned char* buf;
  size_t size, got = 0;

  f = fopen(path, "rb");
  if (!f) {
    smgi_log(&desc->logger, SMG_LOG_ERROR, "cannot open '%s': %s", path,
             strerror(errno));
    return SMG_ERROR_IO;
  }
  if (fstat(fileno(f), &st) != 0 || !S_ISREG(st.st_mode)) {
    smgi_log(&desc->logger, SMG_LOG_ERROR, "'%s' is not a regular file",
             path);
    fclose(f);
    return SMG_ERROR_IO;
  }
  if (st.st_size < 0 || (uint64_t)st.st_size > SMGI_MAX_BLOB_FILE) {
    smgi_log(&desc->logger, SMG_LOG_ERROR,
             "'%s' is %lld bytes, more than the 1 GiB graph limit", path,
             (long long)st.st_size);
    fclose(f);
    return SMG_ERROR_IO;
  }
  size = (size_t)st.st_size;
  buf = (unsigned char*)smgi_alloc(alloc, size, SMGI_BLOB_ALIGN);
  if (!buf) {
    fclose(f);
    return SMG_ERROR_OUT_OF_MEMORY;
  }
  while (got < size) {
    size_t n = fread(buf + got, 1, size - got, f);
    if (n == 0) break;
    got += n;
  }
  /* A file that changed size while we read it is an I/O problem, not a
   * blob problem: report it as such. */
  if (got != size || ferror(f) || fgetc(f) != EOF) {
    smgi_log(&desc->logger, SMG_LOG_ERROR,
             "reading '%s' failed or its size changed", path);
    smgi_free(alloc, buf);
    fclose(f);
    return SMG_ERROR_IO;
  }
  fclose(f);
  *out_buf = buf;
  *out_size = size;
  return SMG_OK;
}

smg_result smg_graph_load_file(const char* path, const smg_graph_desc* desc,
                               smg_graph** out_graph) {
  smg_graph_desc d;
  smg_allocator alloc;
  void* buf = NULL;
  size_t size = 0;
  smg_result res;
  if (!path || !out_graph) return SMG_ERROR_INVALID_ARGUMENT;
  if ((res = resolve_desc(desc, &d, &alloc)) != SMG_OK) return res;
  if ((res = read_file(path, &d, &alloc, &buf, &size)) != SMG_OK) return res;
  res = make_graph(buf, size, buf, &d, &alloc, out_graph);
  if (res != SMG_OK) smgi_free(&alloc, buf);
  return res;
}

smg_result smg_graph_destroy(smg_graph* graph) {
  smg_allocator alloc;
  if (!graph) return SMG_ERROR_INVALID_ARGUMENT;
  if (__atomic_load_n(&graph->character_count, __ATOMIC_ACQUIRE) > 0)
    return SMG_ERROR_IN_USE;
  alloc = graph->allocator;
  smgi_graph_derived_free(graph);
  smgi_free(&alloc, graph->owned_blob);
  smgi_free(&alloc, graph);
  return SMG_OK;
}

void smgi_graph_retain(smg_graph* graph) {
  __atomic_fetch_add(&graph->character_count, 1u, __ATOMIC_ACQ_REL);
}

void smgi_graph_release(smg_graph* graph) {
  __atomic_fetch_sub(&graph->character_count, 1u, __ATOMIC_ACQ_REL);
}

smg_result smg_graph_get_info(const smg_graph* graph,
                              smg_graph_info* out_info) {
  smg_graph_info info;
  const smgi_graph_data* d;
  uint32_t size;
  if (!graph || !out_info) return SMG_ERROR_INVALID_ARGUMENT;
  size = out_info->struct_size;
  if (!smgi_struct_size_ok(size, sizeof info)) return SMG_ERROR_INVALID_ARGUMENT;
  d = &graph->data;
  memset(&info, 0, sizeof info);
  info.struct_size = size;
  info.format_version = graph->format_version;
  info.joint_count = d->joint_count;
  info.style_count = d->style_count;
  info.action_count = d->action_count;
  info.frame_count = d->frame_count;
  info.lower_node_count = d->lower_node_count;
  info.lower_edge_count = d->lower_edge_count;
  info.upper_node_count = d->upper_node_count;
  info.upper_edge_count = d->upper_edge_count;
  info.splice_count = d->splice_count;
  info.character_count =
      __atomic_load_n(&graph->character_count, __ATOMIC_ACQUIRE);
  info.frame_rate = d->info->frame_rate;
  info.blob_size = graph->blob_size;
  memcpy(out_info, &info, size);
  return SMG_OK;
}

smg_result smg_graph_get_joint(const smg_graph* graph, uint32_t index,
                               smg_joint_info* out_joint) {
  smg_joint_info j;
  const smgi_joint* src;
  uint32_t size;
  if (!graph || !out_joint) return SMG_ERROR_INVALID_ARGUMENT;
  size = out_joint->struct_size;
  if (!smgi_struct_size_ok(size, sizeof j)) return SMG_ERROR_INVALID_ARGUMENT;
  if (index >= graph->data.joint_count) return SMG_ERROR_OUT_OF_RANGE;
  src = &graph->data.joints[index];
  memset(&j, 0, sizeof j);
  j.struct_size = size;
  j.parent = src->parent;
  j.name = graph->data.strings + src->name;
  j.rest_offset[0] = src->offset[0];
  j.rest_offset[1] = src->offset[1];
  j.rest_offset[2] = src->offset[2];
  j.body_part = src->body_part;
  memcpy(out_joint, &j, size);
  return SMG_OK;
}

smg_result smg_graph_find_joint(const smg_graph* graph, const char* name,
                                uint32_t* out_index) {
  uint32_t i;
  if (!graph || !name || !out_index) return SMG_ERROR_INVALID_ARGUMENT;
  for (i = 0; i < graph->data.joint_count; ++i) {
    if (strcmp(graph->data.strings + graph->data.joints[i].name, name) == 0) {
      *out_index = i;
      return SMG_OK;
    }
  }
  return SMG_ERROR_NOT_FOUND;
}

static smg_result label_name(const smg_graph* graph, const smgi_label* labels,
                             uint32_t count, uint32_t index,
                             const char** out_name, smg_result unknown) {
  if (!graph || !out_name) return SMG_ERROR_INVALID_ARGUMENT;
  if (index >= count) return unknown;
  *out_name = graph->data.strings + labels[index].name;
  return SMG_OK;
}

static smg_result label_find(const smg_graph* graph, const smgi_label* labels,
                             uint32_t count, const char* name,
                             uint32_t* out_index, smg_result unknown) {
  uint32_t i;
  if (!graph || !name || !out_index) return SMG_ERROR_INVALID_ARGUMENT;
  for (i = 0; i < count; ++i) {
    if (strcmp(graph->data.strings + labels[i].name, name) == 0) {
      *out_index = i;
      return SMG_OK;
    }
  }
  return unknown;
}

smg_result smg_graph_get_style_name(const smg_graph* graph, uint32_t style,
                                    const char** out_name) {
  if (!graph) return SMG_ERROR_INVALID_ARGUMENT;
  return label_name(graph, graph->data.styles, graph->data.style_count, style,
                    out_name, SMG_ERROR_UNKNOWN_STYLE);
}

smg_result smg_graph_find_style(const smg_graph* graph, const char* name,
                                uint32_t* out_style) {
  if (!graph) return SMG_ERROR_INVALID_ARGUMENT;
  return label_find(graph, graph->data.styles, graph->data.style_count, name,
                    out_style, SMG_ERROR_UNKNOWN_STYLE);
}

smg_result smg_graph_get_action_name(const smg_graph* graph, uint32_t action,
                                     const char** out_name) {
  if (!graph) return SMG_ERROR_INVALID_ARGUMENT;
  return label_name(graph, graph->data.actions, graph->data.action_count,
                    action, out_name, SMG_ERROR_UNKNOWN_ACTION);
}

smg_result smg_graph_find_action(const smg_graph* graph, const char* name,
                                 uint32_t* out_action) {
  if (!graph) return SMG_ERROR_INVALID_ARGUMENT;
  return label_find(graph, graph->data.actions, graph->data.action_count,
                    name, out_action, SMG_ERROR_UNKNOWN_ACTION);
}
