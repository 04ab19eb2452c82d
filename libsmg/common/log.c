/*
 * log.c - the one-line logger used for load errors (the caller's optional
 * smg_logger; nothing is printed without one).
 */
#include "log.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>

void smgi_log(const smg_logger* logger, unsigned level, const char* fmt,
              ...) {
  char line[512];
  va_list ap;
  if (!logger || !logger->func || !fmt) return;
  va_start(ap, fmt);
  vsnprintf(line, sizeof line, fmt, ap);
  va_end(ap);
  logger->func((uint32_t)level, line, logger->user);
}
