/*
 * blob_read.c - the validating graph-blob reader (docs/blob-format.md).
 *
 * The runtime trusts nothing it has not checked here: after smgi_blob_read
 * returns SMG_OK every offset, count, index and float the runtime will
 * follow is known to be in range, so the per-frame code needs no checks of
 * its own. Checks run in dependency order (header, section table, section
 * shapes, then record contents) so that each check only relies on facts
 * established before it. All size arithmetic is 64-bit on values that came
 * from 32-bit fields, so nothing can overflow.
 */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "blob.h"
#include "printf_check.h"
#include "quat_pack.h"

/* Largest section alignment accepted (powers of two from 16 up to this). */
#define MAX_SECTION_ALIGN 4096u
/* Magnitude limits. Finite is not enough: a heading of 1e30 rad or a
 * position of 1e30 m is finite but meaningless (float spacing there is
 * astronomically coarse) and makes angle wrapping or accumulation in the
 * runtime degenerate. Real data stays far inside these bounds: 100 km of
 * clip-space travel, 10^4 rad (1600 turns) of unwrapped heading, 1 km
 * joint offsets. */
#define MAX_POSITION 1e5f
#define MAX_ANGLE 1e4f
#define MAX_OFFSET 1e3f

typedef struct reader {
  char* error;
  size_t error_size;
} reader;

SMG_PRINTF_CHECK(3, 4)
static smg_result fail(reader* r, smg_result code, const char* fmt, ...) {
  va_list ap;
  if (r->error && r->error_size > 0) {
    va_start(ap, fmt);
    vsnprintf(r->error, r->error_size, fmt, ap);
    va_end(ap);
  }
  return code;
}

#define CHECK(cond, code, ...)                         \
  do {                                                 \
    if (!(cond)) return fail(r, (code), __VA_ARGS__);  \
  } while (0)

/* finite and |v| <= limit (NaN fails every comparison) */
static int within(float v, float limit) { return v >= -limit && v <= limit; }

static int within3(const float* v, float limit) {
  return within(v[0], limit) && within(v[1], limit) && within(v[2], limit);
}

/* A ground transform (x, z, heading). */
static int ground_ok(const float* g) {
  return within(g[0], MAX_POSITION) && within(g[1], MAX_POSITION) &&
         within(g[2], MAX_ANGLE);
}

static int unit_quat(const float* q) {
  float n;
  if (!isfinite(q[0]) || !isfinite(q[1]) || !isfinite(q[2]) ||
      !isfinite(q[3]))
    return 0;
  n = sqrtf(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  return fabsf(n - 1.0f) <= SMGI_QUAT_UNIT_TOLERANCE;
}

/* ---- section table -------------------------------------------------------- */

enum {
  SEC_INFO, SEC_STRS, SEC_JNTS, SEC_STYL, SEC_ACTN, SEC_CLIP, SEC_POSE,
  SEC_FRMI, SEC_LNOD, SEC_LEDG, SEC_UNOD, SEC_UEDG, SEC_SPLC, SEC_COUNT
};

static const uint32_t k_tags[SEC_COUNT] = {
    SMGI_SEC_INFO, SMGI_SEC_STRS, SMGI_SEC_JNTS, SMGI_SEC_STYL, SMGI_SEC_ACTN,
    SMGI_SEC_CLIP, SMGI_SEC_POSE, SMGI_SEC_FRMI, SMGI_SEC_LNOD, SMGI_SEC_LEDG,
    SMGI_SEC_UNOD, SMGI_SEC_UEDG, SMGI_SEC_SPLC};

/* Record sizes; POSE's depends on the joint count and is checked later. */
static const uint32_t k_record_sizes[SEC_COUNT] = {
    sizeof(smgi_info),  1u,
    sizeof(smgi_joint), sizeof(smgi_label),
    sizeof(smgi_label), sizeof(smgi_clip),
    0u,                 sizeof(smgi_frame),
    sizeof(smgi_node),  sizeof(smgi_edge),
    sizeof(smgi_node),  sizeof(smgi_edge),
    sizeof(smgi_splice)};

static const char* const k_names[SEC_COUNT] = {
    "INFO", "STRS", "JNTS", "STYL", "ACTN", "CLIP", "POSE",
    "FRMI", "LNOD", "LEDG", "UNOD", "UEDG", "SPLC"};

static int tag_index(uint32_t tag) {
  int i;
  for (i = 0; i < SEC_COUNT; ++i)
    if (k_tags[i] == tag) return i;
  return -1;
}

static smg_result read_header(reader* r, const unsigned char* base,
                              size_t size, smgi_blob_header* h) {
  uint32_t i;
  /* Identify the file before complaining about its length, so that a short
   * non-blob file reports "not a blob" rather than "truncated". */
  CHECK(size >= 8, SMG_ERROR_BLOB_TRUNCATED,
        "blob is %zu bytes, shorter than the 8-byte magic", size);
  CHECK(memcmp(base, SMGI_BLOB_MAGIC, 8) == 0, SMG_ERROR_BLOB_MAGIC,
        "header.magic is not \"" SMGI_BLOB_MAGIC "\"");
  CHECK(size >= sizeof(smgi_blob_header), SMG_ERROR_BLOB_TRUNCATED,
        "blob is %zu bytes, shorter than the %zu-byte header", size,
        sizeof(smgi_blob_header));
  memcpy(h, base, sizeof *h);
  CHECK(h->endian == SMGI_BLOB_ENDIAN, SMG_ERROR_BLOB_ENDIAN,
        "header.endian is 0x%08x, expected 0x%08x (other byte order?)",
        (unsigned)h->endian, (unsigned)SMGI_BLOB_ENDIAN);
  CHECK(h->version >= SMG_BLOB_VERSION_MIN, SMG_ERROR_BLOB_VERSION,
        "header.version is %u, this build reads %u..%u: re-bake the graph "
        "with this release's smg-bake",
        (unsigned)h->version, (unsigned)SMG_BLOB_VERSION_MIN,
        (unsigned)SMG_BLOB_VERSION_MAX);
  CHECK(h->version <= SMG_BLOB_VERSION_MAX, SMG_ERROR_BLOB_VERSION,
        "header.version is %u, this build reads %u..%u: the graph needs a "
        "newer libsmg",
        (unsigned)h->version, (unsigned)SMG_BLOB_VERSION_MIN,
        (unsigned)SMG_BLOB_VERSION_MAX);
  CHECK(h->header_size == sizeof(smgi_blob_header), SMG_ERROR_BLOB_VALUE,
        "header.header_size is %u, expected %zu", (unsigned)h->header_size,
        sizeof(smgi_blob_header));
  /* The header is outside the checksum, so every header bit must be
   * checked by value: reserved fields are zero in version 1. */
  CHECK(h->flags == 0, SMG_ERROR_BLOB_VALUE,
        "header.flags is 0x%x, expected 0", (unsigned)h->flags);
  for (i = 0; i < 5; ++i)
    CHECK(h->reserved[i] == 0, SMG_ERROR_BLOB_VALUE,
          "header.reserved[%u] is %u, expected 0", (unsigned)i,
          (unsigned)h->reserved[i]);
  CHECK(h->total_size <= (uint64_t)size, SMG_ERROR_BLOB_TRUNCATED,
        "header.total_size is %llu but only %zu bytes are present",
        (unsigned long long)h->total_size, size);
  CHECK(h->total_size == (uint64_t)size, SMG_ERROR_BLOB_VALUE,
        "header.total_size is %llu but %zu bytes were given",
        (unsigned long long)h->total_size, size);
  CHECK(h->total_size % SMGI_BLOB_ALIGN == 0, SMG_ERROR_BLOB_VALUE,
        "header.total_size %llu is not a multiple of %u",
        (unsigned long long)h->total_size, (unsigned)SMGI_BLOB_ALIGN);
  CHECK(h->section_count <= SMGI_MAX_SECTIONS, SMG_ERROR_BLOB_SECTION,
        "header.section_count is %u, at most %u allowed",
        (unsigned)h->section_count, (unsigned)SMGI_MAX_SECTIONS);
  CHECK(h->header_size + (uint64_t)h->section_count *
                             sizeof(smgi_blob_section) <= h->total_size,
        SMG_ERROR_BLOB_SECTION,
        "section table (%u entries) extends past the end of the blob",
        (unsigned)h->section_count);
  return SMG_OK;
}

static smg_result checksum_result(reader* r, const smgi_blob_header* h,
                                  uint64_t sum) {
  CHECK(sum == h->checksum, SMG_ERROR_BLOB_CHECKSUM,
        "payload checksum is 0x%016llx, header says 0x%016llx",
        (unsigned long long)sum, (unsigned long long)h->checksum);
  return SMG_OK;
}

/* A damaged blob is reported as such: when a structural check fails
 * before the checksum pass, the checksum decides between the two. */
static smg_result checksum_or(reader* r, const unsigned char* base,
                              const smgi_blob_header* h, uint32_t flags,
                              smg_result structural) {
  if (flags & SMG_GRAPH_SKIP_CHECKSUM) return structural;
  uint64_t sum = smgi_blob_checksum(base + h->header_size,
                                    (size_t)(h->total_size - h->header_size));
  return sum != h->checksum ? checksum_result(r, h, sum) : structural;
}

/* Checks every table entry's geometry, finds the required sections (each
 * exactly once; unknown tags are skipped for forward compatibility) and
 * rejects overlaps. found[k] receives the table index of section k. */
static smg_result read_table(reader* r, const unsigned char* base,
                             const smgi_blob_header* h,
                             smgi_blob_section* secs, int* found) {
  uint32_t i, j, n = h->section_count;
  uint32_t order[SMGI_MAX_SECTIONS], used = 0;
  uint64_t table_end =
      h->header_size + (uint64_t)n * sizeof(smgi_blob_section);
  int k;
  for (k = 0; k < SEC_COUNT; ++k) found[k] = -1;
  for (i = 0; i < n; ++i) {
    smgi_blob_section* s = &secs[i];
    char tag[5];
    memcpy(s, base + h->header_size + (uint64_t)i * sizeof *s, sizeof *s);
    memcpy(tag, &s->tag, 4);
    for (j = 0; j < 4; ++j)
      if (tag[j] < 32 || tag[j] > 126) tag[j] = '?';
    tag[4] = '\0';
    CHECK(s->alignment >= SMGI_BLOB_ALIGN &&
              s->alignment <= MAX_SECTION_ALIGN &&
              (s->alignment & (s->alignment - 1)) == 0,
          SMG_ERROR_BLOB_ALIGNMENT,
          "section %u (%s): alignment %u is not a power of two in %u..%u",
          (unsigned)i, tag, (unsigned)s->alignment,
          (unsigned)SMGI_BLOB_ALIGN, (unsigned)MAX_SECTION_ALIGN);
    CHECK(s->offset % s->alignment == 0, SMG_ERROR_BLOB_ALIGNMENT,
          "section %u (%s): offset %llu is not a multiple of %u",
          (unsigned)i, tag, (unsigned long long)s->offset,
          (unsigned)s->alignment);
    CHECK(s->offset >= table_end && s->offset <= h->total_size &&
              s->size <= h->total_size - s->offset,
          SMG_ERROR_BLOB_SECTION,
          "section %u (%s): bytes [%llu, +%llu) not inside the payload "
          "[%llu, %llu)",
          (unsigned)i, tag, (unsigned long long)s->offset,
          (unsigned long long)s->size, (unsigned long long)table_end,
          (unsigned long long)h->total_size);
    CHECK(s->size == (uint64_t)s->count * s->record_size,
          SMG_ERROR_BLOB_SECTION,
          "section %u (%s): size %llu != count %u * record_size %u",
          (unsigned)i, tag, (unsigned long long)s->size, (unsigned)s->count,
          (unsigned)s->record_size);
    k = tag_index(s->tag);
    if (k >= 0) {
      CHECK(found[k] < 0, SMG_ERROR_BLOB_SECTION,
            "section %s appears twice (entries %d and %u)", k_names[k],
            found[k], (unsigned)i);
      CHECK(k_record_sizes[k] == 0 || s->record_size == k_record_sizes[k],
            SMG_ERROR_BLOB_SECTION,
            "section %s: record_size %u, expected %u", k_names[k],
            (unsigned)s->record_size, (unsigned)k_record_sizes[k]);
      found[k] = (int)i;
    }
    if (s->size > 0) {
      /* insertion sort by offset; at most 64 entries */
      j = used++;
      while (j > 0 && secs[order[j - 1]].offset > s->offset) {
        order[j] = order[j - 1];
        --j;
      }
      order[j] = i;
    }
  }
  for (i = 1; i < used; ++i) {
    const smgi_blob_section* a = &secs[order[i - 1]];
    const smgi_blob_section* b = &secs[order[i]];
    CHECK(a->offset + a->size <= b->offset, SMG_ERROR_BLOB_SECTION,
          "sections %u and %u overlap", (unsigned)order[i - 1],
          (unsigned)order[i]);
  }
  for (k = 0; k < SEC_COUNT; ++k)
    CHECK(found[k] >= 0, SMG_ERROR_BLOB_SECTION,
          "required section %s is missing", k_names[k]);
  return SMG_OK;
}

/* ---- contents ------------------------------------------------------------- */

static smg_result check_name(reader* r, const smgi_graph_data* g,
                             const char* sec, uint32_t index, uint32_t name) {
  CHECK(name < g->strings_size, SMG_ERROR_BLOB_INDEX,
        "%s[%u].name: string offset %u >= STRS size %u", sec,
        (unsigned)index, (unsigned)name, (unsigned)g->strings_size);
  return SMG_OK;
}

static smg_result check_info(reader* r, const smgi_graph_data* g) {
  const smgi_info* in = g->info;
  uint32_t J = g->joint_count, i;
  CHECK(isfinite(in->frame_rate) && in->frame_rate > 0.0f &&
            in->frame_rate <= 1000.0f,
        SMG_ERROR_BLOB_VALUE, "INFO[0].frame_rate %g not in (0, 1000]",
        (double)in->frame_rate);
  CHECK(in->joint_count == J, SMG_ERROR_BLOB_SECTION,
        "INFO[0].joint_count %u != JNTS count %u", (unsigned)in->joint_count,
        (unsigned)J);
  CHECK(in->pelvis_joint < J, SMG_ERROR_BLOB_INDEX,
        "INFO[0].pelvis_joint %u >= joint count %u",
        (unsigned)in->pelvis_joint, (unsigned)J);
  CHECK(in->spine_base_joint < J, SMG_ERROR_BLOB_INDEX,
        "INFO[0].spine_base_joint %u >= joint count %u",
        (unsigned)in->spine_base_joint, (unsigned)J);
  for (i = 0; i < 4; ++i) {
    CHECK(in->left_leg[i] < J, SMG_ERROR_BLOB_INDEX,
          "INFO[0].left_leg[%u] %u >= joint count %u", (unsigned)i,
          (unsigned)in->left_leg[i], (unsigned)J);
    CHECK(in->right_leg[i] < J, SMG_ERROR_BLOB_INDEX,
          "INFO[0].right_leg[%u] %u >= joint count %u", (unsigned)i,
          (unsigned)in->right_leg[i], (unsigned)J);
  }
  CHECK(within(in->leg_length, MAX_OFFSET) && in->leg_length >= 0.0f,
        SMG_ERROR_BLOB_VALUE, "INFO[0].leg_length %g not in [0, %g]",
        (double)in->leg_length, (double)MAX_OFFSET);
  CHECK(within(in->ground_height, MAX_POSITION), SMG_ERROR_BLOB_VALUE,
        "INFO[0].ground_height %g not in [-%g, %g]",
        (double)in->ground_height, (double)MAX_POSITION,
        (double)MAX_POSITION);
  CHECK(within(in->window_seconds, 1e3f) && in->window_seconds >= 0.0f,
        SMG_ERROR_BLOB_VALUE, "INFO[0].window_seconds %g not in [0, 1000]",
        (double)in->window_seconds);
  return SMG_OK;
}

static smg_result check_joints(reader* r, const smgi_graph_data* g) {
  uint32_t J = g->joint_count, j;
  smg_result res;
  for (j = 0; j < J; ++j) {
    const smgi_joint* jt = &g->joints[j];
    if ((res = check_name(r, g, "JNTS", j, jt->name)) != SMG_OK) return res;
    if (j == 0)
      CHECK(jt->parent == -1, SMG_ERROR_BLOB_INDEX,
            "JNTS[0].parent is %d, the root must have -1", (int)jt->parent);
    else
      CHECK(jt->parent >= 0 && (uint32_t)jt->parent < j,
            SMG_ERROR_BLOB_INDEX,
            "JNTS[%u].parent is %d, must be in [0, %u) (parents first)",
            (unsigned)j, (int)jt->parent, (unsigned)j);
    CHECK(jt->body_part <= SMG_BODY_UPPER, SMG_ERROR_BLOB_VALUE,
          "JNTS[%u].body_part %u is not ROOT/LOWER/UPPER", (unsigned)j,
          (unsigned)jt->body_part);
    CHECK(jt->mirror < J, SMG_ERROR_BLOB_INDEX,
          "JNTS[%u].mirror %u >= joint count %u", (unsigned)j,
          (unsigned)jt->mirror, (unsigned)J);
    CHECK(within3(jt->offset, MAX_OFFSET), SMG_ERROR_BLOB_VALUE,
          "JNTS[%u].offset is not finite within %g m", (unsigned)j,
          (double)MAX_OFFSET);
    CHECK(isfinite(jt->mass_ratio) && jt->mass_ratio >= 0.0f &&
              jt->mass_ratio <= 1.0f,
          SMG_ERROR_BLOB_VALUE, "JNTS[%u].mass_ratio %g not in [0, 1]",
          (unsigned)j, (double)jt->mass_ratio);
  }
  /* second pass: every mirror is now known to be in range */
  for (j = 0; j < J; ++j)
    CHECK(g->joints[g->joints[j].mirror].mirror == j, SMG_ERROR_BLOB_INDEX,
          "JNTS[%u].mirror %u does not mirror back", (unsigned)j,
          (unsigned)g->joints[j].mirror);
  return SMG_OK;
}

static smg_result check_labels(reader* r, const smgi_graph_data* g) {
  uint32_t i;
  smg_result res;
  CHECK(g->style_count >= 1, SMG_ERROR_BLOB_SECTION,
        "STYL is empty: at least one locomotion style is required");
  CHECK(g->action_count >= 1, SMG_ERROR_BLOB_SECTION,
        "ACTN is empty: action 0 \"none\" is required");
  for (i = 0; i < g->style_count; ++i)
    if ((res = check_name(r, g, "STYL", i, g->styles[i].name)) != SMG_OK)
      return res;
  for (i = 0; i < g->action_count; ++i)
    if ((res = check_name(r, g, "ACTN", i, g->actions[i].name)) != SMG_OK)
      return res;
  CHECK(strcmp(g->strings + g->actions[0].name, "none") == 0,
        SMG_ERROR_BLOB_VALUE, "ACTN[0] is \"%.32s\", must be \"none\"",
        g->strings + g->actions[0].name);
  return SMG_OK;
}

static smg_result check_clips(reader* r, const smgi_graph_data* g) {
  uint32_t i;
  smg_result res;
  for (i = 0; i < g->clip_count; ++i) {
    const smgi_clip* c = &g->clips[i];
    if ((res = check_name(r, g, "CLIP", i, c->name)) != SMG_OK) return res;
    CHECK((uint64_t)c->first_frame + c->frame_count <= g->frame_count,
          SMG_ERROR_BLOB_INDEX,
          "CLIP[%u] frames [%u, +%u) beyond POSE frame count %u",
          (unsigned)i, (unsigned)c->first_frame, (unsigned)c->frame_count,
          (unsigned)g->frame_count);
    if (c->flags & SMGI_CLIP_LOWER)
      CHECK(c->label < g->style_count, SMG_ERROR_BLOB_INDEX,
            "CLIP[%u].label (style) %u >= style count %u", (unsigned)i,
            (unsigned)c->label, (unsigned)g->style_count);
    if (c->flags & SMGI_CLIP_UPPER)
      CHECK(c->label < g->action_count, SMG_ERROR_BLOB_INDEX,
            "CLIP[%u].label (action) %u >= action count %u", (unsigned)i,
            (unsigned)c->label, (unsigned)g->action_count);
    CHECK(c->source_clip == SMGI_NONE || c->source_clip < g->clip_count,
          SMG_ERROR_BLOB_INDEX, "CLIP[%u].source_clip %u >= clip count %u",
          (unsigned)i, (unsigned)c->source_clip, (unsigned)g->clip_count);
  }
  return SMG_OK;
}

/* Frame f's POSE and FRMI records, with the reason of the first failure.
 * Only the root translations need checking: every 48-bit rotation pattern
 * decodes to a finite unit quaternion (quat_pack.h), so the J rotations of
 * a frame carry no invalid values (version 1 tested each float quaternion
 * for unit length here, a third of a load). */
static smg_result check_frame(reader* r, const smgi_graph_data* g,
                              uint32_t f) {
  const smgi_frame* fr = &g->frames[f];
  float p[3];
  smgi_pose_root(smgi_pose_record(g, f), p);
  CHECK(within3(p, MAX_POSITION), SMG_ERROR_BLOB_VALUE,
        "POSE[%u] root translation is not finite within %g m", (unsigned)f,
        (double)MAX_POSITION);
  CHECK(ground_ok(fr->root2d), SMG_ERROR_BLOB_VALUE,
        "FRMI[%u].root2d is not finite within %g m / %g rad", (unsigned)f,
        (double)MAX_POSITION, (double)MAX_ANGLE);
  CHECK(fr->clip < g->clip_count, SMG_ERROR_BLOB_INDEX,
        "FRMI[%u].clip %u >= clip count %u", (unsigned)f, (unsigned)fr->clip,
        (unsigned)g->clip_count);
  CHECK(isfinite(fr->phase) && fr->phase >= -1.0f && fr->phase <= 1.0f,
        SMG_ERROR_BLOB_VALUE, "FRMI[%u].phase %g not in [-1, 1]", (unsigned)f,
        (double)fr->phase);
  return SMG_OK;
}

/* The same checks, for frames [a, b) of one section at a time (POSE and
 * FRMI are checked as the checksum pass reaches them): the first failing
 * frame, or b. A frame's conditions are combined without branches (| of
 * comparisons; NaN fails every one), one branch per frame: these loops run
 * over millions of frames in a big graph. */
static uint32_t scan_poses(const smgi_graph_data* g, uint32_t a, uint32_t b) {
  const float L = MAX_POSITION;
  for (uint32_t f = a; f < b; ++f) {
    float p[3];
    smgi_pose_root(smgi_pose_record(g, f), p);
    if (!((fabsf(p[0]) <= L) & (fabsf(p[1]) <= L) & (fabsf(p[2]) <= L)))
      return f;
  }
  return b;
}

static uint32_t scan_frames(const smgi_graph_data* g, uint32_t a,
                            uint32_t b) {
  const float L = MAX_POSITION, H = MAX_ANGLE;
  for (uint32_t f = a; f < b; ++f) {
    const smgi_frame* fr = &g->frames[f];
    if (!((fabsf(fr->root2d[0]) <= L) & (fabsf(fr->root2d[1]) <= L) &
          (fabsf(fr->root2d[2]) <= H) & (fr->clip < g->clip_count) &
          (fabsf(fr->phase) <= 1.0f)))
      return f;
  }
  return b;
}

/* Records of `count` (record_size > 0 bytes from `offset`) that lie
 * wholly before byte `pos`. */
static uint32_t records_before(uint64_t pos, uint64_t offset,
                               uint64_t record_size, uint32_t count) {
  if (pos <= offset) return 0;
  const uint64_t n = (pos - offset) / record_size;
  return n < count ? (uint32_t)n : count;
}

/* Bytes hashed between record checks: small enough that the records just
 * hashed are still in the L1/L2 cache when they are checked, so a load
 * reads the blob from memory once, not once for the checksum and again
 * for the checks (two thirds of a 490 MB blob's validation was the second
 * pass over POSE and FRMI). A multiple of the checksum's 64-byte block. */
#define STREAM_CHUNK ((uint64_t)32768u)

/* The checksum pass and the POSE and FRMI checks together. The checksum
 * wins: a blob whose checksum does not match is reported as damaged even
 * when a record check failed first. Among record failures the lowest
 * frame is reported, POSE before FRMI, as a frame-by-frame loop would. */
static smg_result check_frames_streamed(reader* r, const unsigned char* base,
                                        const smgi_blob_header* h,
                                        uint32_t flags,
                                        const smgi_graph_data* g,
                                        uint64_t pose_offset,
                                        uint64_t frmi_offset) {
  const uint32_t F = g->frame_count;
  const uint64_t pose_size = SMGI_POSE_RECORD_SIZE(g->joint_count);
  uint32_t pose_done = 0, frmi_done = 0, pose_bad = F, frmi_bad = F;
  if (flags & SMG_GRAPH_SKIP_CHECKSUM) {
    pose_bad = scan_poses(g, 0, F);
    frmi_bad = scan_frames(g, 0, F);
  } else {
    const uint64_t end = h->total_size;
    uint64_t pos = h->header_size;
    smgi_wh64 wh;
    smgi_wh64_begin(&wh);
    while (pos < end) {
      uint64_t next = end - pos > STREAM_CHUNK ? pos + STREAM_CHUNK : end;
      const uint64_t whole = (next - pos) & ~(uint64_t)63u;
      smgi_wh64_blocks(&wh, base + pos, (size_t)whole);
      if (next == end) {
        const uint64_t sum = smgi_wh64_end(
            &wh, base + pos + whole, (size_t)(next - pos - whole),
            (size_t)(end - h->header_size));
        smg_result res = checksum_result(r, h, sum);
        if (res != SMG_OK) return res;
      }
      pos = next;
      if (pose_bad == F) {
        const uint32_t upto = records_before(pos, pose_offset, pose_size, F);
        pose_bad = scan_poses(g, pose_done, upto);
        if (pose_bad == upto) pose_bad = F;
        pose_done = upto;
      }
      if (frmi_bad == F) {
        const uint32_t upto =
            records_before(pos, frmi_offset, sizeof(smgi_frame), F);
        frmi_bad = scan_frames(g, frmi_done, upto);
        if (frmi_bad == upto) frmi_bad = F;
        frmi_done = upto;
      }
    }
  }
  /* the reason, from the frame-by-frame check of the first bad frame */
  const uint32_t bad = pose_bad < frmi_bad ? pose_bad : frmi_bad;
  return bad < F ? check_frame(r, g, bad) : SMG_OK;
}

/* One motion graph (lower or upper): node/edge cross references. */
static smg_result check_graph(reader* r, const smgi_graph_data* g,
                              const char* nsec, const char* esec,
                              const smgi_node* nodes, uint32_t node_count,
                              const smgi_edge* edges, uint32_t edge_count,
                              uint32_t label_count) {
  uint64_t next = 0;
  uint32_t n, e;
  CHECK(node_count > 0 || edge_count == 0, SMG_ERROR_BLOB_INDEX,
        "%s has %u edges but %s has no nodes", esec, (unsigned)edge_count,
        nsec);
  for (n = 0; n < node_count; ++n) {
    const smgi_node* nd = &nodes[n];
    CHECK(nd->frame < g->frame_count, SMG_ERROR_BLOB_INDEX,
          "%s[%u].frame %u >= POSE frame count %u", nsec, (unsigned)n,
          (unsigned)nd->frame, (unsigned)g->frame_count);
    CHECK(nd->label < label_count, SMG_ERROR_BLOB_INDEX,
          "%s[%u].label %u >= label count %u", nsec, (unsigned)n,
          (unsigned)nd->label, (unsigned)label_count);
    /* Out-edges are contiguous and in node order, so the nodes' ranges
     * must tile [0, edge_count) exactly. */
    CHECK(nd->first_edge == next, SMG_ERROR_BLOB_INDEX,
          "%s[%u].first_edge %u, expected %llu (edges sorted by node)", nsec,
          (unsigned)n, (unsigned)nd->first_edge, (unsigned long long)next);
    CHECK(next + nd->edge_count <= edge_count, SMG_ERROR_BLOB_INDEX,
          "%s[%u] edges [%u, +%u) beyond %s count %u", nsec, (unsigned)n,
          (unsigned)nd->first_edge, (unsigned)nd->edge_count, esec,
          (unsigned)edge_count);
    for (e = nd->first_edge; e < nd->first_edge + nd->edge_count; ++e)
      CHECK(edges[e].from == n, SMG_ERROR_BLOB_INDEX,
            "%s[%u].from %u, but it lies in node %u's range", esec,
            (unsigned)e, (unsigned)edges[e].from, (unsigned)n);
    next += nd->edge_count;
  }
  CHECK(next == edge_count, SMG_ERROR_BLOB_INDEX,
        "%s: nodes cover %llu edges but %s has %u", nsec,
        (unsigned long long)next, esec, (unsigned)edge_count);
  for (e = 0; e < edge_count; ++e) {
    const smgi_edge* ed = &edges[e];
    CHECK(ed->to < node_count, SMG_ERROR_BLOB_INDEX,
          "%s[%u].to %u >= node count %u", esec, (unsigned)e,
          (unsigned)ed->to, (unsigned)node_count);
    CHECK(ed->frame_count >= 1, SMG_ERROR_BLOB_VALUE,
          "%s[%u].frame_count is 0", esec, (unsigned)e);
    CHECK((uint64_t)ed->first_frame + ed->frame_count <= g->frame_count,
          SMG_ERROR_BLOB_INDEX,
          "%s[%u] frames [%u, +%u) beyond POSE frame count %u", esec,
          (unsigned)e, (unsigned)ed->first_frame, (unsigned)ed->frame_count,
          (unsigned)g->frame_count);
    CHECK(ground_ok(ed->displacement), SMG_ERROR_BLOB_VALUE,
          "%s[%u].displacement is not finite within %g m / %g rad", esec,
          (unsigned)e, (double)MAX_POSITION, (double)MAX_ANGLE);
    CHECK(within(ed->arc_length, MAX_POSITION) && ed->arc_length >= 0.0f,
          SMG_ERROR_BLOB_VALUE, "%s[%u].arc_length not in [0, %g]", esec,
          (unsigned)e, (double)MAX_POSITION);
    CHECK(isfinite(ed->cost) && ed->cost >= 0.0f, SMG_ERROR_BLOB_VALUE,
          "%s[%u].cost is not finite and >= 0", esec, (unsigned)e);
    CHECK(ed->label < label_count, SMG_ERROR_BLOB_INDEX,
          "%s[%u].label %u >= label count %u", esec, (unsigned)e,
          (unsigned)ed->label, (unsigned)label_count);
  }
  return SMG_OK;
}

static smg_result check_splices(reader* r, const smgi_graph_data* g) {
  uint32_t i;
  for (i = 0; i < g->splice_count; ++i) {
    const smgi_splice* s = &g->splices[i];
    CHECK(s->lower_frame < g->frame_count, SMG_ERROR_BLOB_INDEX,
          "SPLC[%u].lower_frame %u >= POSE frame count %u", (unsigned)i,
          (unsigned)s->lower_frame, (unsigned)g->frame_count);
    CHECK(s->action < g->action_count, SMG_ERROR_BLOB_INDEX,
          "SPLC[%u].action %u >= action count %u", (unsigned)i,
          (unsigned)s->action, (unsigned)g->action_count);
    CHECK(s->upper_edge < g->upper_edge_count, SMG_ERROR_BLOB_INDEX,
          "SPLC[%u].upper_edge %u >= UEDG count %u", (unsigned)i,
          (unsigned)s->upper_edge, (unsigned)g->upper_edge_count);
    CHECK(s->upper_offset < g->upper_edges[s->upper_edge].frame_count,
          SMG_ERROR_BLOB_INDEX,
          "SPLC[%u].upper_offset %u >= UEDG[%u] frame count %u", (unsigned)i,
          (unsigned)s->upper_offset, (unsigned)s->upper_edge,
          (unsigned)g->upper_edges[s->upper_edge].frame_count);
    CHECK(isfinite(s->distance) && s->distance >= 0.0f, SMG_ERROR_BLOB_VALUE,
          "SPLC[%u].distance is not finite and >= 0", (unsigned)i);
    CHECK(unit_quat(s->correction), SMG_ERROR_BLOB_VALUE,
          "SPLC[%u].correction is not a finite unit quaternion",
          (unsigned)i);
  }
  return SMG_OK;
}

/* Section shapes that depend on other sections, the view of every
 * section, and the checks of the small ones (everything before POSE). */
static smg_result map_sections(reader* r, const unsigned char* base,
                               const smgi_blob_section* secs,
                               const int* found, smgi_graph_data* g) {
  const smgi_blob_section* s;
  uint64_t pose_record;
  smg_result res;
  CHECK(secs[found[SEC_INFO]].count == 1, SMG_ERROR_BLOB_SECTION,
        "INFO has %u records, expected 1",
        (unsigned)secs[found[SEC_INFO]].count);
  s = &secs[found[SEC_POSE]];
  /* SMGI_POSE_RECORD_SIZE in 64 bits: the count is not yet bounded */
  pose_record =
      (12u + 6u * (uint64_t)secs[found[SEC_JNTS]].count + 3u) & ~(uint64_t)3u;
  CHECK(s->record_size == pose_record, SMG_ERROR_BLOB_SECTION,
        "POSE record_size %u, expected %llu for %u joints",
        (unsigned)s->record_size, (unsigned long long)pose_record,
        (unsigned)secs[found[SEC_JNTS]].count);
  CHECK(secs[found[SEC_FRMI]].count == s->count, SMG_ERROR_BLOB_SECTION,
        "FRMI has %u records but POSE has %u frames",
        (unsigned)secs[found[SEC_FRMI]].count, (unsigned)s->count);

  memset(g, 0, sizeof *g);
#define SEC_PTR(k) (base + secs[found[k]].offset)
#define SEC_COUNT_OF(k) (secs[found[k]].count)
  g->info = (const smgi_info*)SEC_PTR(SEC_INFO);
  g->strings = (const char*)SEC_PTR(SEC_STRS);
  g->strings_size = SEC_COUNT_OF(SEC_STRS);
  g->joints = (const smgi_joint*)SEC_PTR(SEC_JNTS);
  g->joint_count = SEC_COUNT_OF(SEC_JNTS);
  g->styles = (const smgi_label*)SEC_PTR(SEC_STYL);
  g->style_count = SEC_COUNT_OF(SEC_STYL);
  g->actions = (const smgi_label*)SEC_PTR(SEC_ACTN);
  g->action_count = SEC_COUNT_OF(SEC_ACTN);
  g->clips = (const smgi_clip*)SEC_PTR(SEC_CLIP);
  g->clip_count = SEC_COUNT_OF(SEC_CLIP);
  g->poses = SEC_PTR(SEC_POSE);
  g->frame_count = SEC_COUNT_OF(SEC_POSE);
  g->frames = (const smgi_frame*)SEC_PTR(SEC_FRMI);
  g->lower_nodes = (const smgi_node*)SEC_PTR(SEC_LNOD);
  g->lower_node_count = SEC_COUNT_OF(SEC_LNOD);
  g->lower_edges = (const smgi_edge*)SEC_PTR(SEC_LEDG);
  g->lower_edge_count = SEC_COUNT_OF(SEC_LEDG);
  g->upper_nodes = (const smgi_node*)SEC_PTR(SEC_UNOD);
  g->upper_node_count = SEC_COUNT_OF(SEC_UNOD);
  g->upper_edges = (const smgi_edge*)SEC_PTR(SEC_UEDG);
  g->upper_edge_count = SEC_COUNT_OF(SEC_UEDG);
  g->splices = (const smgi_splice*)SEC_PTR(SEC_SPLC);
  g->splice_count = SEC_COUNT_OF(SEC_SPLC);
#undef SEC_PTR
#undef SEC_COUNT_OF

  CHECK(g->strings_size > 0 && g->strings[g->strings_size - 1] == '\0',
        SMG_ERROR_BLOB_VALUE, "STRS must be non-empty and end with NUL");
  if ((res = check_info(r, g)) != SMG_OK) return res;
  if ((res = check_joints(r, g)) != SMG_OK) return res;
  if ((res = check_labels(r, g)) != SMG_OK) return res;
  if ((res = check_clips(r, g)) != SMG_OK) return res;
  return SMG_OK;
}

smg_result smgi_blob_read(const void* data, size_t size, uint32_t flags,
                          smgi_graph_data* out, char* error,
                          size_t error_size) {
  reader rd, *r = &rd;
  const unsigned char* base = (const unsigned char*)data;
  smgi_blob_header h;
  smgi_blob_section secs[SMGI_MAX_SECTIONS];
  int found[SEC_COUNT];
  smgi_graph_data g;
  smg_result res;

  rd.error = error;
  rd.error_size = error_size;
  if (error && error_size > 0) error[0] = '\0';
  CHECK(data != NULL && out != NULL, SMG_ERROR_INVALID_ARGUMENT,
        "smgi_blob_read: data and out must not be NULL");
  CHECK((flags & ~(uint32_t)SMG_GRAPH_SKIP_CHECKSUM) == 0,
        SMG_ERROR_INVALID_ARGUMENT, "smgi_blob_read: unknown flags 0x%x",
        (unsigned)flags);
  CHECK(((uintptr_t)data & (SMGI_BLOB_ALIGN - 1)) == 0,
        SMG_ERROR_BLOB_ALIGNMENT, "blob memory is not %u-byte aligned",
        (unsigned)SMGI_BLOB_ALIGN);
  if ((res = read_header(r, base, size, &h)) != SMG_OK) return res;
  /* Checks of the small sections run first; where one fails, the
   * checksum decides whether the blob is damaged (checksum_or). The
   * checksum itself is computed in the pass that checks POSE and FRMI. */
  if ((res = read_table(r, base, &h, secs, found)) != SMG_OK)
    return checksum_or(r, base, &h, flags, res);

  if ((res = map_sections(r, base, secs, found, &g)) != SMG_OK)
    return checksum_or(r, base, &h, flags, res);
  if ((res = check_frames_streamed(
           r, base, &h, flags, &g, secs[found[SEC_POSE]].offset,
           secs[found[SEC_FRMI]].offset)) != SMG_OK)
    return res;
  if ((res = check_graph(r, &g, "LNOD", "LEDG", g.lower_nodes,
                         g.lower_node_count, g.lower_edges,
                         g.lower_edge_count, g.style_count)) != SMG_OK)
    return res;
  if ((res = check_graph(r, &g, "UNOD", "UEDG", g.upper_nodes,
                         g.upper_node_count, g.upper_edges,
                         g.upper_edge_count, g.action_count)) != SMG_OK)
    return res;
  if ((res = check_splices(r, &g)) != SMG_OK) return res;
  *out = g;
  return SMG_OK;
}
