/*
 * bake_write_file.c - smg_bake_write_file: the blob to disk atomically.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "bake_desc.h"
#include "file_replace.h"
#include "smg_bake.h"


/* The blob goes to a fresh temporary file beside `path` (same directory,
 * so the rename cannot cross file systems), is flushed to the disk, and
 * only then renamed over `path`: readers see the old file or the whole new
 * one, never a part, even if the bake fails or is killed half-way (an
 * interrupted write leaves only a hidden .NAME.XXXXXX beside it). */
smg_result smg_bake_write_file(const smg_bake_result* result,
                               const char* path, char* error,
                               size_t error_size) {
  char tmp[4096];
  const char* base;
  FILE* f;
  size_t n;
  int fd, ok;
  if (error && error_size) error[0] = '\0';
  if (!result || !smgb_result_holds_blob(result->struct_size) ||
      !result->blob || !path || !path[0]) {
    if (error && error_size)
      snprintf(error, error_size, "smg_bake_write_file: no blob or no path");
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  base = smg_file_base(path);
  if (snprintf(tmp, sizeof tmp, "%.*s.%s.XXXXXX", (int)(base - path), path,
               base) >= (int)sizeof tmp) {
    if (error && error_size)
      snprintf(error, error_size, "%s: path too long", path);
    return SMG_ERROR_INVALID_ARGUMENT;
  }
  fd = mkstemp(tmp);
  if (fd < 0) {
    if (error && error_size)
      snprintf(error, error_size, "%s: cannot create a file beside it (%s)",
               path, strerror(errno));
    return SMG_ERROR_IO;
  }
  smg_file_keep_mode(fd, path);
  f = fdopen(fd, "wb");
  if (!f) {
    close(fd);
    remove(tmp);
    if (error && error_size)
      snprintf(error, error_size, "%s: cannot open for writing", tmp);
    return SMG_ERROR_IO;
  }
  n = fwrite(result->blob, 1, result->blob_size, f);
  ok = n == result->blob_size && fflush(f) == 0 && smg_file_sync(fd) == 0;
  if (fclose(f) != 0 || !ok) {
    remove(tmp);
    if (error && error_size)
      snprintf(error, error_size, "%s: write failed (disk full?); %s is "
               "unchanged", tmp, path);
    return SMG_ERROR_IO;
  }
  if (smg_file_replace(tmp, path) != 0) {
    remove(tmp);
    if (error && error_size)
      snprintf(error, error_size, "%s: cannot rename to %s", tmp, path);
    return SMG_ERROR_IO;
  }
  return SMG_OK;
}
