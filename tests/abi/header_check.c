/*
 * header_check.c - smg.h must compile warning-free as strict C99 and as
 * C++11 (this same file is built both ways by `make test-header`) and its
 * functions must link from C++ (extern "C").
 */
#include "smg.h"
#include "smg.h" /* include guard */

#include <stdio.h>
#include <string.h>

/* Every public struct is usable with zero-initialisation. */
static int check(void) {
  smg_graph_desc gd;
  smg_character_desc cd;
  smg_graph_info gi;
  smg_joint_info ji;
  smg_character_state cs;
  smg_graph* g = NULL;
  memset(&gd, 0, sizeof gd);
  memset(&cd, 0, sizeof cd);
  memset(&gi, 0, sizeof gi);
  memset(&ji, 0, sizeof ji);
  memset(&cs, 0, sizeof cs);
  gd.struct_size = (uint32_t)sizeof gd;
  if (smg_version() != (uint32_t)SMG_VERSION) return 1;
  if (smg_result_string(SMG_OK) == NULL) return 1;
  if (smg_graph_load_memory(NULL, 0, &gd, &g) != SMG_ERROR_INVALID_ARGUMENT)
    return 1;
  return (int)(sizeof cd + sizeof gi + sizeof ji + sizeof cs) > 0 ? 0 : 1;
}

int main(void) {
  int r = check();
  printf("header check (%s): %s\n",
#ifdef __cplusplus
         "C++",
#else
         "C",
#endif
         r == 0 ? "ok" : "FAILED");
  return r;
}
