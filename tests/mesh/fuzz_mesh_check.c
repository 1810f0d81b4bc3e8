/* fuzz_mesh_check.c - libFuzzer entry point for one mesh checker, chosen at
 * build time (VSH_FUZZ_CHECK, see CMakeLists.txt: fuzz_mesh_obj, _ply, _stl,
 * _vtp). The contract is the mutation test's: return, stay inside the buffer
 * (ASan), and reject with a non-empty one-line message. */
#include "vsh_mesh_check.h"

#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  char err[512] = "";
  if (VSH_FUZZ_CHECK((const char *)data, size, err, sizeof err) != 0 &&
      (err[0] == '\0' || strchr(err, '\n')))
    abort();
  return 0;
}
