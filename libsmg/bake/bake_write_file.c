/*
 * bake_write_file.c - smg_bake_write_file: the blob to disk atomically.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#ifdef _WIN32
#include <io.h>
#include <windows.h>
#endif

#include "bake_desc.h"
#include "smg_bake.h"

/* The platform parts of writing a file in place. Windows has no file mode
 * bits to keep, flushes a descriptor with _commit, and its rename() refuses
 * an existing target: MoveFileEx replaces it (one call, atomic on NTFS
 * within a directory). */
#ifdef _WIN32
static void keep_mode(int fd, const char* path) {
  (void)fd;
  (void)path;
}
static int sync_fd(int fd) { return _commit(fd); }
static int replace_file(const char* from, const char* to) {
  return MoveFileExA(from, to, MOVEFILE_REPLACE_EXISTING |
                                   MOVEFILE_WRITE_THROUGH) ? 0 : -1;
}
static const char* path_base(const char* path) {
  const char* slash = strrchr(path, '/');
  const char* back = strrchr(path, '\\');
  if (back && (!slash || back > slash)) slash = back;
  return slash ? slash + 1 : path;
}
#else
/* mkstemp makes it private (0600): keep the old file's mode, else the
 * usual 0644 */
static void keep_mode(int fd, const char* path) {
  struct stat st;
  fchmod(fd, stat(path, &st) == 0 ? (st.st_mode & 07777) : 0644);
}
static int sync_fd(int fd) { return fsync(fd); }
static int replace_file(const char* from, const char* to) {
  return rename(from, to);
}
static const char* path_base(const char* path) {
  const char* slash = strrchr(path, '/');
  return slash ? slash + 1 : path;
}
#endif

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
  base = path_base(path);
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
  keep_mode(fd, path);
  f = fdopen(fd, "wb");
  if (!f) {
    close(fd);
    remove(tmp);
    if (error && error_size)
      snprintf(error, error_size, "%s: cannot open for writing", tmp);
    return SMG_ERROR_IO;
  }
  n = fwrite(result->blob, 1, result->blob_size, f);
  ok = n == result->blob_size && fflush(f) == 0 && sync_fd(fd) == 0;
  if (fclose(f) != 0 || !ok) {
    remove(tmp);
    if (error && error_size)
      snprintf(error, error_size, "%s: write failed (disk full?); %s is "
               "unchanged", tmp, path);
    return SMG_ERROR_IO;
  }
  if (replace_file(tmp, path) != 0) {
    remove(tmp);
    if (error && error_size)
      snprintf(error, error_size, "%s: cannot rename to %s", tmp, path);
    return SMG_ERROR_IO;
  }
  return SMG_OK;
}
