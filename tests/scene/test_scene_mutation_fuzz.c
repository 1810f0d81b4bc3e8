/* test_scene_mutation_fuzz.c - deterministic mutation fuzzing of the parser.
 *
 * Starting from each good scene given on the command line, applies thousands
 * of seeded random mutations (bit flips, deletions, insertions of JSON
 * punctuation, numbers swapped for huge/negative/odd values, keys swapped for
 * other valid keys, truncation) and checks the contract of vsh_scene_parse:
 *   - failure: *out is NULL, the message is non-empty, one line, and starts
 *     with the file name;
 *   - success: a scene whose primitives all tessellate, with unit normals.
 * Run under ASan/UBSan (VTKSHADOW_SANITIZE=ON) this also catches memory errors.
 * Same seed, same mutations: a failure reproduces with the printed iteration.
 * Usage: test_scene_mutation_fuzz GOOD.json... (env VSH_FUZZ_ITERATIONS, default 20000)
 */
#include "vsh_check.h"
#include "vsh_mutate.h"
#include "vsh_scene.h"

#include <stdint.h>
#include <stdlib.h>
#include <time.h>

/* Finds a token of the given class starting at a random place; returns its
 * start and length, or 0 if there is none. */
static int find_number(const mm_buf *b, size_t *at, size_t *n) {
  size_t i, start = mm_below(b->len);
  for (i = 0; i < b->len; ++i) {
    size_t p = (start + i) % b->len;
    if (b->data[p] >= '0' && b->data[p] <= '9') {
      size_t s = p, e = p;
      while (s > 0 && mm_num_char(b->data[s - 1])) --s;
      while (e < b->len && mm_num_char(b->data[e])) ++e;
      *at = s;
      *n = e - s;
      return 1;
    }
  }
  return 0;
}
static int find_string(const mm_buf *b, size_t *at, size_t *n) {
  size_t i, start = mm_below(b->len);
  for (i = 0; i < b->len; ++i) {
    size_t p = (start + i) % b->len, e;
    if (b->data[p] != '"') continue;
    for (e = p + 1; e < b->len && b->data[e] != '"'; ++e) {
    }
    if (e < b->len) {
      *at = p;
      *n = e - p + 1;
      return 1;
    }
  }
  return 0;
}

static const char *const values[] = {
    "1e999", "-1e999", "-1",  "0",     "1e308",   "-1e308",  "1e-320", "99999999999", "-0",
    "0.5",   "4096",   "4097", "16385", "2",      "3",       "180",    "90",          "1e-300",
    "\"x\"", "null",   "true", "false", "[]",     "{}",      "[1,2,3]", "[0,0,0]",    "\"\"",
    "[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1]", "[0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,1]", "1.0000000001"};
static const char *const keys[] = {
    "\"sphere\"",   "\"plane\"",      "\"box\"",        "\"cylinder\"", "\"mesh\"",
    "\"receiver\"", "\"casts\"",      "\"color\"",      "\"name\"",     "\"transform\"",
    "\"type\"",     "\"directional\"", "\"point\"",      "\"spot\"",     "\"cone_angle\"",
    "\"position\"", "\"focal_point\"", "\"view_up\"",    "\"radius\"",   "\"resolution\"",
    "\"size\"",     "\"lights\"",     "\"objects\"",    "\"camera\"",   "\"meshes/tri.obj\"",
    "\"meshes/nope.ply\"", "\"/\"",   "\"meshes\"",     "\"recever\"",  "\"\\u0000\"",
    "\"mirror\"", "\"opacity\"", "\"filter\""};
static const char punct[] = "0123456789\"[]{},:-.e \n\\";

static void mutate(mm_buf *b) {
  size_t at, n;
  switch (mm_below(8)) {
  case 0: /* flip a bit */
    if (b->len) b->data[mm_below(b->len)] ^= (char)(1u << mm_below(8));
    break;
  case 1: /* delete a span */
    if (b->len) {
      at = mm_below(b->len);
      mm_erase(b, at, 1 + mm_below(8));
    }
    break;
  case 2: { /* insert JSON punctuation or digits */
    char c = punct[mm_below(sizeof punct - 1)];
    mm_insert(b, mm_below(b->len + 1), &c, 1);
    break;
  }
  case 3: /* swap a number for an odd value */
    if (find_number(b, &at, &n)) {
      const char *v = values[mm_below(sizeof values / sizeof values[0])];
      mm_erase(b, at, n);
      mm_insert(b, at, v, strlen(v));
    }
    break;
  case 4: /* swap a string (key or value) for another valid-looking one */
    if (find_string(b, &at, &n)) {
      const char *k = keys[mm_below(sizeof keys / sizeof keys[0])];
      mm_erase(b, at, n);
      mm_insert(b, at, k, strlen(k));
    }
    break;
  case 5: /* duplicate a span elsewhere (duplicate keys, nested arrays) */
    if (b->len) {
      char tmp[64];
      at = mm_below(b->len);
      n = 1 + mm_below(sizeof tmp);
      if (at + n > b->len) n = b->len - at;
      memcpy(tmp, b->data + at, n);
      mm_insert(b, mm_below(b->len + 1), tmp, n);
    }
    break;
  case 6: /* truncate */
    if (b->len) b->len = mm_below(b->len + 1);
    break;
  default: /* negate a number */
    if (find_number(b, &at, &n)) mm_insert(b, at, "-", 1);
    break;
  }
}

/* A validated scene must tessellate: the parser's checks and the
 * tessellator's preconditions have to agree. */
static void check_scene(const vsh_scene *s, const char *path, long iteration) {
  size_t i, k;
  CHECK(s->light_count > 0 && s->object_count > 0);
  for (i = 0; i < s->light_count; ++i)
    if (s->lights[i].type == VSH_LIGHT_DIRECTIONAL)
      CHECK_NEAR(sqrt(s->lights[i].direction[0] * s->lights[i].direction[0] +
                      s->lights[i].direction[1] * s->lights[i].direction[1] +
                      s->lights[i].direction[2] * s->lights[i].direction[2]),
                 1, 1e-12);
  /* Light sizes that passed validation are usable: finite, a radius >= 0,
   * an angle with a finite tangent, and only on the kind that has one. */
  for (i = 0; i < s->light_count; ++i) {
    const vsh_light *l = &s->lights[i];
    CHECK(isfinite(l->radius) && l->radius >= 0.0);
    CHECK(l->angle >= 0.0 && l->angle < 180.0 && isfinite(tan(l->angle * 0.008726646259971648)));
    CHECK(l->type == VSH_LIGHT_DIRECTIONAL ? l->radius == 0.0 : l->angle == 0.0);
  }
  for (i = 0; i < s->object_count; ++i) {
    const vsh_object *o = &s->objects[i];
    vsh_mesh m;
    int rc;
    /* A mirror is a plane with a reflectance the renderers can blend by. */
    if (o->has_mirror) CHECK(o->kind == VSH_OBJECT_PLANE && o->mirror >= 0 && o->mirror <= 1);
    if (!o->has_mirror) CHECK(o->mirror == 0);
    /* Translucency is a fraction; a mirror is opaque. */
    CHECK(o->opacity >= 0 && o->opacity <= 1 && o->filter >= 0 && o->filter <= 1);
    if (o->has_mirror) CHECK(o->opacity == 1);
    if (o->kind == VSH_OBJECT_MESH) {
      CHECK(o->mesh_path && o->mesh_resolved_path);
      continue;
    }
    /* Keep the run short: huge resolutions are valid but slow to tessellate. */
    if ((o->kind == VSH_OBJECT_SPHERE || o->kind == VSH_OBJECT_CYLINDER) && o->resolution > 512)
      continue;
    rc = vsh_object_tessellate(o, &m);
    CHECK(rc == 0);
    if (rc) {
      fprintf(stderr, "  %s iteration %ld: object %zu (%s) did not tessellate\n", path, iteration,
              i, vsh_object_kind_name(o->kind));
      continue;
    }
    for (k = 0; k < m.point_count; ++k) {
      const double *n = m.normals + 3 * k;
      double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (!(fabs(l - 1) < 1e-9)) {
        CHECK(fabs(l - 1) < 1e-9);
        fprintf(stderr, "  %s iteration %ld: object %zu normal length %g\n", path, iteration, i,
                l);
        break;
      }
    }
    vsh_mesh_free(&m);
  }
}

int main(int argc, char **argv) {
  long iterations = 20000, it;
  const char *env = getenv("VSH_FUZZ_ITERATIONS");
  int f;
  clock_t start = clock();
  if (env) iterations = atol(env);
  CHECK(argc > 1);
  for (f = 1; f < argc; ++f) {
    const char *path = argv[f];
    size_t seed_len = 0, path_len = strlen(path);
    char *seed = mm_read_file(path, &seed_len);
    long ok = 0, failed = 0;
    CHECK(seed != NULL);
    if (!seed) continue;
    for (it = 0; it < iterations; ++it) {
      mm_buf b = {NULL, 0, 0};
      char err[VSH_SCENE_ERROR_MAX];
      vsh_scene *s = (vsh_scene *)&b; /* any non-NULL value: parse must reset it */
      int m, mutations = 1 + (int)(it % 4), rc;
      mm_state = 0x5eed0000ull + (uint64_t)f * 1000003ull + (uint64_t)it;
      mm_reserve(&b, seed_len);
      memcpy(b.data, seed, seed_len);
      b.len = seed_len;
      for (m = 0; m < mutations; ++m) mutate(&b);
      /* An exact-size copy without terminator: under ASan, any read past
       * `length` by the parser is caught. */
      {
        char *exact = (char *)malloc(b.len ? b.len : 1);
        if (!exact) abort();
        memcpy(exact, b.data, b.len);
        rc = vsh_scene_parse(exact, b.len, path, &s, err, sizeof err);
        free(exact);
      }
      if (rc == 0) {
        ++ok;
        CHECK(s != NULL);
        if (s) check_scene(s, path, it);
        vsh_scene_free(s);
      } else {
        ++failed;
        CHECK(s == NULL);
        CHECK(err[0] != '\0');
        CHECK(strncmp(err, path, path_len) == 0 && err[path_len] == ':');
        CHECK(strchr(err, '\n') == NULL);
        if (s != NULL || strncmp(err, path, path_len) != 0 || strchr(err, '\n'))
          fprintf(stderr, "  iteration %ld: bad message \"%s\"\n", it, err);
      }
      free(b.data);
    }
    printf("%s: %ld mutations, %ld parsed, %ld rejected\n", path, iterations, ok, failed);
    CHECK(ok > 0 && failed > 0); /* the mutations explore both sides */
    free(seed);
  }
  printf("%.1f s CPU\n", (double)(clock() - start) / CLOCKS_PER_SEC);
  return vsh_check_report("scene.mutation_fuzz");
}
