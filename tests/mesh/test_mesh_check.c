/* test_mesh_check.c - unit test of the mesh checkers (vsh_mesh_check.h): the
 * seed corpus passes, and each malformed-input class is refused with the
 * message that names the problem. The same classes go through
 * vtkshadow-render in tests/cli/test_bad_input.py.
 * Usage: test_mesh_check CORPUS_DIR */
#include "vsh_check.h"
#include "vsh_mesh_check.h"

#include <stdint.h>
#include <stdlib.h>

typedef int (*checker)(const char *, size_t, char *, size_t);

static void bad(checker check, const char *data, size_t size, const char *needle, int line) {
  char err[512] = "";
  int rc = check(data, size, err, sizeof err);
  CHECK(rc != 0);
  CHECK_STR_CONTAINS(err, needle);
  if (rc == 0 || !strstr(err, needle)) fprintf(stderr, "  (case at line %d)\n", line);
}
#define BAD(check, text, needle) bad(check, text, sizeof(text) - 1, needle, __LINE__)

static void good(checker check, const char *data, size_t size, int line) {
  char err[512] = "";
  int rc = check(data, size, err, sizeof err);
  CHECK(rc == 0);
  if (rc) fprintf(stderr, "  (case at line %d: %s)\n", line, err);
}
#define GOOD(check, text) good(check, text, sizeof(text) - 1, __LINE__)

#define TETRA_V "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
static void test_obj(void) {
  GOOD(vsh_obj_check_buffer, TETRA_V "f 1 2 3\nf -4 -3 -1\nf 1/1 2/1 3/1\nvt 0 0\n");
  GOOD(vsh_obj_check_buffer, TETRA_V "vn 0 0 1\nf 1//1 2//1 3//-1\n# f 9 9 9\n");
  BAD(vsh_obj_check_buffer, TETRA_V "f 1 2 3\nf 1 2 5\n",
      "line 6: face 2 refers to vertex 5 but the file has 4");
  BAD(vsh_obj_check_buffer, TETRA_V "f 0 1 2\n", "face 1 refers to vertex 0 (OBJ indices start at 1)");
  BAD(vsh_obj_check_buffer, "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n",
      "face 1 refers to vertex -3, before the first one (only 2 precede it)");
  BAD(vsh_obj_check_buffer, TETRA_V "vt 0 0\nf 1/1 2/2 3/1\n",
      "face 1 refers to texture coordinate 2 but the file has 1");
  BAD(vsh_obj_check_buffer, TETRA_V "f 1//1 2//1 3//1\n", "refers to normal 1 but the file has 0");
  BAD(vsh_obj_check_buffer, "v nan 0 0\n", "vertex 1 has a coordinate that is not a finite float");
  BAD(vsh_obj_check_buffer, "v 0 -inf 0\n", "not a finite float (got \"-inf\")");
  BAD(vsh_obj_check_buffer, "v 0 0 1e39\n", "not a finite float (got \"1e39\")");
  BAD(vsh_obj_check_buffer, "v 0 0\n", "vertex 1 has fewer than 3 numbers");
  BAD(vsh_obj_check_buffer, TETRA_V "f 1 2\n", "face 1 has 2 vertices (a face needs at least 3)");
  BAD(vsh_obj_check_buffer, TETRA_V "f 1 x 2\n", "vertex index that is not an integer (got \"x\")");
  BAD(vsh_obj_check_buffer, TETRA_V "f 1/1/1/1 2 3\n", "more than three indices");
  BAD(vsh_obj_check_buffer, TETRA_V "l 1 7\n", "line 1 refers to vertex 7");
  BAD(vsh_obj_check_buffer, "v 0 0 0\0\n", "NUL bytes");
}

#define PLY_HEAD(fmt, nv, nf) "ply\nformat " fmt " 1.0\nelement vertex " nv "\nproperty float x\n" \
  "property float y\nproperty float z\nelement face " nf "\nproperty list uchar int vertex_indices\nend_header\n"
#define PLY_V "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
static void test_ply(void) {
  GOOD(vsh_ply_check_buffer, PLY_HEAD("ascii", "4", "2") PLY_V "3 0 1 2\n4 0 1 2 3\n");
  BAD(vsh_ply_check_buffer, PLY_HEAD("ascii", "4", "2") PLY_V "3 0 1 2\n3 0 1 7\n",
      "face 1 refers to vertex 7 but the file has 4");
  BAD(vsh_ply_check_buffer, PLY_HEAD("ascii", "4", "1") PLY_V "3 0 -1 2\n",
      "face 0 refers to vertex -1 but the file has 4");
  BAD(vsh_ply_check_buffer, PLY_HEAD("ascii", "4", "2") PLY_V "3 0 1 2\n", "truncated PLY file");
  BAD(vsh_ply_check_buffer, PLY_HEAD("ascii", "4", "1") PLY_V "3 0 1 2", "face 0 is not ended by a newline");
  BAD(vsh_ply_check_buffer, PLY_HEAD("ascii", "4", "1") "0 0 0\n1 0\n0 1 0\n0 0 1\n3 0 1 2\n",
      "line 11: vertex 1 has too few values");
  BAD(vsh_ply_check_buffer, PLY_HEAD("ascii", "4", "1") "0 0 0\n\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n",
      "vertex 1 has too few values");
  BAD(vsh_ply_check_buffer, PLY_HEAD("ascii", "4", "1") "0 nan 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n",
      "vertex 0 has a coordinate y that is not a finite float");
  BAD(vsh_ply_check_buffer, PLY_HEAD("ascii", "4", "1") "0 abc 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n",
      "not a number (got \"abc\")");
  BAD(vsh_ply_check_buffer, PLY_HEAD("ascii", "4", "1") PLY_V "2 0 1\n",
      "face 0 has 2 vertices (3 to 255 are supported)");
  BAD(vsh_ply_check_buffer, PLY_HEAD("ascii", "4000000000", "1") PLY_V,
      "element \"vertex\" has 4000000000 entries, over the limit of 50000000");
  BAD(vsh_ply_check_buffer, PLY_HEAD("ascii", "4", "60000000") PLY_V, "over the limit of 50000000");
  BAD(vsh_ply_check_buffer, "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n",
      "unknown type");
  BAD(vsh_ply_check_buffer, "ply\nformat ascii 1.0\nelement face 1\nproperty list float int "
      "vertex_indices\nend_header\n", "count type that is not an integer type");
  BAD(vsh_ply_check_buffer, "ply\nformat ascii 1.0\nelement vertex 1\nproperty list uchar float x\n"
      "end_header\n", "\"x\" must not be a list");
  BAD(vsh_ply_check_buffer, "ply\nformat ascii 1.0\nelement vertex 1\n", "no end_header");
  BAD(vsh_ply_check_buffer, "ply\nformat xml 1.0\nend_header\n", "unknown PLY format");
  BAD(vsh_ply_check_buffer, "plx\n", "not a PLY file");
  BAD(vsh_ply_check_buffer, "ply\nformat ascii 1.0\n\nelement vertex 1\n", "line 3: blank line in the PLY header");
  BAD(vsh_ply_check_buffer, "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
      "property float 5y\nproperty float z\nend_header\n0 0 0\n", "lacks one of the properties x, y, z");
  BAD(vsh_ply_check_buffer, "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
      "end_header\n3 0 1 2\n", "declares no \"vertex\" element");
  {
    /* binary: little and big endian, index past the end, truncation, inf, negative count */
    static const char head[] = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                               "property float x\nproperty float y\nproperty float z\nelement face 1\n"
                               "property list char int vertex_indices\nend_header\n";
    char buf[256];
    size_t n = sizeof head - 1;
    const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const int32_t f[3] = {0, 1, 2};
    memcpy(buf, head, n);
    memcpy(buf + n, v, sizeof v);
    buf[n + sizeof v] = 3;
    memcpy(buf + n + sizeof v + 1, f, sizeof f);
    good(vsh_ply_check_buffer, buf, n + sizeof v + 1 + sizeof f, __LINE__);
    bad(vsh_ply_check_buffer, buf, n + sizeof v + 1 + sizeof f - 1, "truncated PLY file: the body "
        "ends in face 0 of 1", __LINE__);
    buf[n + sizeof v + 1 + 8] = 3; /* third index 3 */
    bad(vsh_ply_check_buffer, buf, n + sizeof v + 1 + sizeof f,
        "face 0 refers to vertex 3 but the file has 3", __LINE__);
    buf[n + sizeof v] = -1;
    bad(vsh_ply_check_buffer, buf, n + sizeof v + 1 + sizeof f, "has a bad length (got -1)",
        __LINE__);
    memcpy(buf + n + 4, "\x00\x00\x80\x7f", 4); /* +inf */
    bad(vsh_ply_check_buffer, buf, n + sizeof v + 1 + sizeof f, "vertex 0 has a coordinate y that "
        "is not a finite float", __LINE__);
  }
}

static void stl_binary(char *buf, uint32_t claimed, float x) {
  uint32_t i;
  memset(buf, 0, 84 + 50);
  memcpy(buf, "binary", 6);
  buf[79] = (char)0x80; /* a few high bytes so that VTK's type detection says binary */
  for (i = 0; i < 20; ++i) buf[20 + i] = (char)0xff;
  memcpy(buf + 80, &claimed, 4);
  memcpy(buf + 84 + 12 + 12, &x, 4); /* second corner's x */
}

static void test_stl(void) {
  char buf[134];
  GOOD(vsh_stl_check_buffer, "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                             "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n");
  BAD(vsh_stl_check_buffer, "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                            "vertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid t\n",
      "line 7: expected \"endloop\"");
  BAD(vsh_stl_check_buffer, "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 nan 0\n",
      "line 4: facet 1 has a vertex coordinate that is not a finite float (got \"nan\")");
  BAD(vsh_stl_check_buffer, "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 1e39\n",
      "not a finite float (got \"1e39\")");
  BAD(vsh_stl_check_buffer, "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 zero 0\n",
      "vertex is not 3 numbers");
  BAD(vsh_stl_check_buffer, "hello\n", "expected \"solid\"");
  stl_binary(buf, 1, 1.0f);
  good(vsh_stl_check_buffer, buf, sizeof buf, __LINE__);
  stl_binary(buf, 2147483648u, 1.0f);
  bad(vsh_stl_check_buffer, buf, sizeof buf, "binary STL header says 2147483648 triangles but the "
      "file holds only 1", __LINE__);
  stl_binary(buf, 1, 1.0f);
  bad(vsh_stl_check_buffer, buf, sizeof buf - 1, "header says 1 triangles but the file holds only 0",
      __LINE__);
  stl_binary(buf, 0, 1.0f);
  bad(vsh_stl_check_buffer, buf, sizeof buf - 1, "not a whole number of 50-byte triangles", __LINE__);
  bad(vsh_stl_check_buffer, buf, 60, "shorter than the 84-byte header", __LINE__);
  stl_binary(buf, 1, (float)(1e30 * 1e30 * 1e30));
  bad(vsh_stl_check_buffer, buf, sizeof buf, "triangle 1 has a vertex coordinate that is not finite",
      __LINE__);
  BAD(vsh_stl_check_buffer, "solid \x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f", "cannot tell");
}

#define VTP(points, polys) "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\">" \
  "<PolyData><Piece NumberOfPoints=\"" points "\" NumberOfPolys=\"" polys "\">" \
  "</Piece></PolyData></VTKFile>\n"
static void test_vtp(void) {
  uint64_t tris = 0;
  const int32_t off[] = {0, 3, 6}, conn[] = {0, 1, 2, 2, 1, 3}, bad_conn[] = {0, 1, 2, 2, 1, 4};
  const int32_t down[] = {0, 3, 2}, long_off[] = {0, 3, 7};
  const int64_t off64[] = {0, 3}, conn64[] = {0, -1, 2};
  const double pts[] = {0, 0, 0, 1, 0, 0, 0, 1, 0}, npts[] = {0, 0, 0, 1, 0, 0, 0, 1.0 / 0.0 * 0.0, 0};
  vsh_cell_arrays c = {off, conn, 0, 3, 6};
  char err[512] = "";
  GOOD(vsh_vtp_check_buffer, VTP("4", "2"));
  BAD(vsh_vtp_check_buffer, VTP("3000000000", "2"), "NumberOfPoints adds up to 3000000000, over the limit");
  BAD(vsh_vtp_check_buffer, VTP("4", "60000000"), "NumberOfPolys adds up to 60000000");
  BAD(vsh_vtp_check_buffer, VTP("-4", "2"), "Piece 1: NumberOfPoints is not a count");
  BAD(vsh_vtp_check_buffer, "<VTKFile type=\"UnstructuredGrid\"></VTKFile>", "not of type PolyData");
  BAD(vsh_vtp_check_buffer, "<VTKFile type=\"PolyData\"><PolyData></PolyData></VTKFile>", "no <Piece>");
  BAD(vsh_vtp_check_buffer, "hello", "not a VTK XML file");
  BAD(vsh_vtp_check_buffer, "<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"1\">"
      "<Points><DataArray type=\"Float64\" NumberOfComponents=\"-1\"/></Points></Piece>",
      "DataArray 1: NumberOfComponents is not a count from 1 to 1024");
  CHECK(vsh_cells_check(&c, "polygon", 4, &tris, err, sizeof err) == 0 && tris == 2);
  c.connectivity = bad_conn;
  CHECK(vsh_cells_check(&c, "polygon", 4, &tris, err, sizeof err) != 0);
  CHECK_STR_CONTAINS(err, "polygon 1 refers to point 4 but the file has 4");
  c.connectivity = conn;
  c.offsets = down;
  CHECK(vsh_cells_check(&c, "polygon", 4, NULL, err, sizeof err) != 0);
  CHECK_STR_CONTAINS(err, "polygon 1 has offset 2 after 3");
  c.offsets = long_off;
  CHECK(vsh_cells_check(&c, "polygon", 4, NULL, err, sizeof err) != 0);
  CHECK_STR_CONTAINS(err, "polygon 1 has offset 7 after 3 (connectivity has 6 ids)");
  c.offsets = off;
  c.connectivity_count = 7;
  CHECK(vsh_cells_check(&c, "polygon", 4, NULL, err, sizeof err) != 0);
  CHECK_STR_CONTAINS(err, "offsets end at 6 but connectivity has 7 ids");
  {
    vsh_cell_arrays c64 = {off64, conn64, 1, 2, 3};
    CHECK(vsh_cells_check(&c64, "strip", 4, NULL, err, sizeof err) != 0);
    CHECK_STR_CONTAINS(err, "strip 0 refers to point -1");
  }
  CHECK(vsh_points_check_double(pts, 3, err, sizeof err) == 0);
  CHECK(vsh_points_check_double(npts, 3, err, sizeof err) != 0);
  CHECK_STR_CONTAINS(err, "point 2 has a coordinate that is not finite");
}

/* Every seed of the fuzz corpus passes its checker. */
static void test_corpus(const char *dir) {
  static const char *const seeds[] = {
      "obj/tetra.obj", "obj/cube.obj", "ply/tetra-ascii.ply", "ply/tetra-binary_little_endian.ply",
      "ply/tetra-binary_big_endian.ply", "ply/tetra-texcoord.ply", "stl/tetra-ascii.stl",
      "stl/tetra-binary.stl", "vtp/tetra-ascii.vtp", "vtp/tetra-binary.vtp",
      "vtp/tetra-appended.vtp", "vtp/tetra-zlib.vtp", "vtp/tetra-double.vtp"};
  size_t i;
  for (i = 0; i < sizeof seeds / sizeof seeds[0]; ++i) {
    char path[1024], err[512] = "";
    const char *ext = strrchr(seeds[i], '.');
    int rc;
    snprintf(path, sizeof path, "%s/%s", dir, seeds[i]);
    rc = strcmp(ext, ".obj") == 0   ? vsh_obj_check(path, err, sizeof err)
         : strcmp(ext, ".ply") == 0 ? vsh_ply_check(path, err, sizeof err)
         : strcmp(ext, ".stl") == 0 ? vsh_stl_check(path, err, sizeof err)
                                    : vsh_vtp_check(path, err, sizeof err);
    CHECK(rc == 0);
    if (rc) fprintf(stderr, "  %s: %s\n", path, err);
  }
  {
    char err[512] = "";
    CHECK(vsh_obj_check("/nonexistent/x.obj", err, sizeof err) != 0);
    CHECK_STR_CONTAINS(err, "cannot open");
  }
}

int main(int argc, char **argv) {
  CHECK(argc == 2);
  test_obj();
  test_ply();
  test_stl();
  test_vtp();
  if (argc == 2) test_corpus(argv[1]);
  return vsh_check_report("mesh.check");
}
