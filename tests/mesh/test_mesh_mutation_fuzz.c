/* test_mesh_mutation_fuzz.c - deterministic mutation fuzzing of the mesh
 * checkers (C, no VTK; also runs in the sanitizer build).
 *
 * For each seed file (its extension picks the checker) applies thousands of
 * seeded mutations (mesh_mutate.h) and checks the checker's contract: it
 * returns, never reads past the buffer (an exact-size copy, so ASan sees any
 * overread), and a rejection comes with a non-empty one-line message. Both
 * outcomes must occur for every seed, or the mutations explore nothing.
 * Whether VTK's readers survive what the checkers accept is tested by
 * test_mesh_read_fuzz (VTK build).
 * Usage: test_mesh_mutation_fuzz SEED... (env VSH_FUZZ_ITERATIONS, default 20000) */
#include "mesh_mutate.h"
#include "vsh_check.h"
#include "vsh_mesh_check.h"

#include <stdio.h>
#include <time.h>

typedef int (*checker)(const char *, size_t, char *, size_t);

static checker checker_for(const char *path) {
  const char *dot = strrchr(path, '.');
  if (!dot) return NULL;
  if (strcmp(dot, ".obj") == 0) return vsh_obj_check_buffer;
  if (strcmp(dot, ".ply") == 0) return vsh_ply_check_buffer;
  if (strcmp(dot, ".stl") == 0) return vsh_stl_check_buffer;
  if (strcmp(dot, ".vtp") == 0) return vsh_vtp_check_buffer;
  return NULL;
}

int main(int argc, char **argv) {
  long iterations = 20000, it;
  const char *env = getenv("VSH_FUZZ_ITERATIONS");
  clock_t start = clock();
  int f;
  if (env) iterations = atol(env);
  CHECK(argc > 1);
  for (f = 1; f < argc; ++f) {
    size_t seed_len = 0;
    char *seed = mm_read_file(argv[f], &seed_len);
    checker check = checker_for(argv[f]);
    mm_buf b = {NULL, 0, 0};
    long ok = 0, failed = 0;
    char err[512];
    CHECK(seed != NULL && check != NULL);
    if (!seed || !check) continue;
    CHECK(check(seed, seed_len, err, sizeof err) == 0); /* the seed itself is good */
    for (it = 0; it < iterations; ++it) {
      char *exact;
      int rc;
      mm_make(&b, seed, seed_len, f, it);
      exact = (char *)malloc(b.len ? b.len : 1);
      if (!exact) abort();
      memcpy(exact, b.data, b.len);
      err[0] = '\0';
      rc = check(exact, b.len, err, sizeof err);
      free(exact);
      if (rc == 0) {
        ++ok;
      } else {
        ++failed;
        if (err[0] == '\0' || strchr(err, '\n')) {
          CHECK(err[0] != '\0' && !strchr(err, '\n'));
          fprintf(stderr, "  %s iteration %ld: bad message \"%s\"\n", argv[f], it, err);
        }
      }
    }
    printf("%s: %ld mutations, %ld accepted, %ld rejected\n", argv[f], iterations, ok, failed);
    CHECK(ok > 0 && failed > 0);
    free(b.data);
    free(seed);
  }
  printf("%.1f s CPU\n", (double)(clock() - start) / CLOCKS_PER_SEC);
  return vsh_check_report("mesh.mutation_fuzz");
}
