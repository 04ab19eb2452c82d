/*
 * file_replace.h - the platform parts of replacing a file atomically (a
 * temporary file beside the target, flushed, then renamed over it), shared
 * by the baker's blob writer and the glTF writer. Header-only: the runtime
 * library itself writes no files.
 *
 * Windows has no file mode bits to keep, flushes a descriptor with
 * _commit, and its rename() refuses an existing target: MoveFileEx
 * replaces it (one call, atomic on NTFS within a directory). Paths may use
 * either separator there.
 */
#ifndef SMG_FILE_REPLACE_H
#define SMG_FILE_REPLACE_H

#include <string.h>
#include <sys/stat.h>
#ifdef _WIN32
#include <io.h>
#include <windows.h>
#else
#include <stdio.h>
#include <unistd.h>
#endif

#ifdef _WIN32
static inline int smg_file_keep_mode(int fd, const char* path) {
  (void)fd;
  (void)path;
  return 0;
}
static inline int smg_file_sync(int fd) { return _commit(fd); }
static inline int smg_file_replace(const char* from, const char* to) {
  return MoveFileExA(from, to, MOVEFILE_REPLACE_EXISTING |
                                   MOVEFILE_WRITE_THROUGH) ? 0 : -1;
}
static inline const char* smg_file_base(const char* path) {
  const char* slash = strrchr(path, '/');
  const char* back = strrchr(path, '\\');
  if (back && (!slash || back > slash)) slash = back;
  return slash ? slash + 1 : path;
}
#else
/* mkstemp makes the temporary file private (0600): keep the old file's
 * mode, else the usual 0644 */
static inline int smg_file_keep_mode(int fd, const char* path) {
  struct stat st;
  return fchmod(fd, stat(path, &st) == 0 ? (st.st_mode & 07777) : 0644);
}
static inline int smg_file_sync(int fd) { return fsync(fd); }
static inline int smg_file_replace(const char* from, const char* to) {
  return rename(from, to);
}
static inline const char* smg_file_base(const char* path) {
  const char* slash = strrchr(path, '/');
  return slash ? slash + 1 : path;
}
#endif

#endif
