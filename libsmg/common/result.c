/*
 * result.c - library version and the names of smg_result codes.
 * Kept apart from everything else so an engine can print an error without
 * touching any other part of the library.
 */
#include "smg.h"

uint32_t smg_version(void) { return (uint32_t)SMG_VERSION; }

const char* smg_result_string(smg_result result) {
  /* A switch rather than a table: the compiler checks every enumerator is
   * handled (-Wswitch) and unknown values fall through to the default. */
  switch (result) {
    case SMG_OK:
      return "SMG_OK: success";
    case SMG_ERROR_INVALID_ARGUMENT:
      return "SMG_ERROR_INVALID_ARGUMENT: NULL pointer, non-finite number, "
             "bad struct_size or unknown flag";
    case SMG_ERROR_OUT_OF_MEMORY:
      return "SMG_ERROR_OUT_OF_MEMORY: the allocator returned NULL";
    case SMG_ERROR_IO:
      return "SMG_ERROR_IO: file could not be opened or read";
    case SMG_ERROR_BLOB_TRUNCATED:
      return "SMG_ERROR_BLOB_TRUNCATED: blob shorter than its header says";
    case SMG_ERROR_BLOB_MAGIC:
      return "SMG_ERROR_BLOB_MAGIC: not a libsmg graph blob";
    case SMG_ERROR_BLOB_ENDIAN:
      return "SMG_ERROR_BLOB_ENDIAN: blob written with the other byte order";
    case SMG_ERROR_BLOB_VERSION:
      return "SMG_ERROR_BLOB_VERSION: blob format version not supported by "
             "this build";
    case SMG_ERROR_BLOB_ALIGNMENT:
      return "SMG_ERROR_BLOB_ALIGNMENT: blob memory or a section is "
             "misaligned";
    case SMG_ERROR_BLOB_CHECKSUM:
      return "SMG_ERROR_BLOB_CHECKSUM: payload checksum mismatch";
    case SMG_ERROR_BLOB_SECTION:
      return "SMG_ERROR_BLOB_SECTION: section table entry invalid, "
             "duplicated or missing";
    case SMG_ERROR_BLOB_INDEX:
      return "SMG_ERROR_BLOB_INDEX: an index inside a section is out of "
             "range";
    case SMG_ERROR_BLOB_VALUE:
      return "SMG_ERROR_BLOB_VALUE: a non-finite or impossible value in the "
             "blob";
    case SMG_ERROR_UNKNOWN_STYLE:
      return "SMG_ERROR_UNKNOWN_STYLE: style not in the graph";
    case SMG_ERROR_UNKNOWN_ACTION:
      return "SMG_ERROR_UNKNOWN_ACTION: action not in the graph";
    case SMG_ERROR_OUT_OF_RANGE:
      return "SMG_ERROR_OUT_OF_RANGE: index or arc length beyond the valid "
             "range";
    case SMG_ERROR_CAPACITY:
      return "SMG_ERROR_CAPACITY: a fixed capacity is full";
    case SMG_ERROR_BUFFER_TOO_SMALL:
      return "SMG_ERROR_BUFFER_TOO_SMALL: caller buffer smaller than needed";
    case SMG_ERROR_IN_USE:
      return "SMG_ERROR_IN_USE: graph still has live characters";
    case SMG_ERROR_NOT_FOUND:
      return "SMG_ERROR_NOT_FOUND: name or id not found";
    case SMG_ERROR_PARSE:
      return "SMG_ERROR_PARSE: malformed input file";
    case SMG_ERROR_UNSUPPORTED:
      return "SMG_ERROR_UNSUPPORTED: valid request this build cannot do";
    case SMG_RESULT_FORCE_32:
      break;
  }
  return "SMG_ERROR_UNKNOWN: not an smg_result value";
}
