/* vsh_csm_status.c - names of the csm calls' status codes, for messages. */
#include "vsh_csm.h"

const char *vsh_csm_status_name(vsh_csm_status status)
{
  switch (status) {
  case VSH_CSM_OK:
    return "ok";
  case VSH_CSM_EMPTY:
    return "empty";
  case VSH_CSM_BAD_INPUT:
    return "bad input";
  case VSH_CSM_TARGET_MISSED:
    return "target missed";
  }
  return "unknown status";
}
