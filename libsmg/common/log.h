/*
 * log.h - logging through the caller's optional smg_logger (graph load).
 */
#ifndef SMG_LOG_H
#define SMG_LOG_H

#include "printf_check.h"
#include "smg.h"

/* Logging through an optional logger; printf-style, one line. */
void smgi_log(const smg_logger* logger, unsigned level, const char* fmt, ...)
    SMG_PRINTF_CHECK(3, 4)
    ;

#endif /* SMG_LOG_H */
