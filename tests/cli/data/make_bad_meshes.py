#!/usr/bin/env python3
"""Writes tests/cli/data/meshes/bad/: one small file per malformed-input class
per mesh format, each one that crashed or fooled vtkshadow-render before the
mesh checkers (issue 11). test_bad_input.py pairs each file with the words
its message must contain (BAD_MESHES below). Run: python3 tests/cli/data/make_bad_meshes.py"""
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "mesh"))
from make_corpus import TETRA_CONN, TETRA_OFFSETS, TETRA_POINTS, vtp_bytes  # noqa: E402

V4 = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
PLY_HEAD = ("ply\nformat {fmt} 1.0\nelement vertex {nv}\nproperty float x\nproperty float y\n"
            "property float z\nelement face {nf}\nproperty list uchar int vertex_indices\nend_header\n")
PLY_V = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"


def ply_binary(fmt, faces, nv=4, cut=0):
    e = "<" if fmt == "binary_little_endian" else ">"
    data = PLY_HEAD.format(fmt=fmt, nv=nv, nf=len(faces)).encode()
    data += b"".join(struct.pack(e + "3f", *TETRA_POINTS[3 * i:3 * i + 3]) for i in range(4))
    data += b"".join(struct.pack(e + "B%di" % len(f), len(f), *f) for f in faces)
    return data[:len(data) - cut] if cut else data


def stl_binary(count, coords=None, extra=b""):
    data = b"\xffbinary".ljust(80, b"\xff") + struct.pack("<I", count)
    tris = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    for n, t in enumerate(tris):
        data += struct.pack("<3f", 0, 0, 1)
        pts = [TETRA_POINTS[3 * i:3 * i + 3] for i in t]
        if coords is not None and n == 1:
            pts[0] = coords
        data += b"".join(struct.pack("<3f", *p) for p in pts) + b"\0\0"
    return data + extra


def stl_ascii(vertex_lines):
    return ("solid t\nfacet normal 0 0 1\nouter loop\n" + "".join(f"vertex {v}\n" for v in vertex_lines)
            + "endloop\nendfacet\nendsolid t\n")


# file name -> (contents, words the message must contain)
BAD_MESHES = {
    # OBJ
    "obj-index-past-end.obj": (V4 + "f 1 2 3\nf 1 2 1200\n", "face 2 refers to vertex 1200 but the file has 4"),
    "obj-index-zero.obj": (V4 + "f 0 1 2\n", "refers to vertex 0 (OBJ indices start at 1)"),
    "obj-index-negative.obj": (V4 + "f -1 -2 -5\n", "refers to vertex -5, before the first one"),
    "obj-texcoord-past-end.obj": (V4 + "vt 0 0\nf 1/1 2/1 3/2\n", "refers to texture coordinate 2"),
    "obj-normal-past-end.obj": (V4 + "vn 0 0 1\nf 1//1 2//1 3//3\n", "refers to normal 3 but the file has 1"),
    "obj-nan.obj": ("v nan 0 0\n" + V4 + "f 2 3 4\n", "vertex 1 has a coordinate that is not a finite float"),
    "obj-inf.obj": (V4 + "v 0 inf 0\nf 1 2 3\n", "not a finite float (got \"inf\")"),
    "obj-float-overflow.obj": (V4 + "v 0 0 1e39\nf 1 2 3\n", "not a finite float (got \"1e39\")"),
    "obj-short-vertex.obj": ("v 0 0\n" + V4 + "f 2 3 4\n", "vertex 1 has fewer than 3 numbers"),
    "obj-two-corner-face.obj": (V4 + "f 1 2\n", "face 1 has 2 vertices"),
    "obj-bad-index.obj": (V4 + "f 1 two 3\n", "not an integer (got \"two\")"),
    "obj-binary-junk.obj": (V4 + "f 1 2 3\n\0\0\0", "not a text file"),
    # PLY
    "ply-ascii-index-past-end.ply": (PLY_HEAD.format(fmt="ascii", nv=4, nf=2) + PLY_V + "3 0 1 2\n3 0 1 1000\n",
                                     "face 1 refers to vertex 1000 but the file has 4"),
    "ply-ascii-index-negative.ply": (PLY_HEAD.format(fmt="ascii", nv=4, nf=1) + PLY_V + "3 0 -1 2\n",
                                     "face 0 refers to vertex -1"),
    "ply-binary-le-index-past-end.ply": (ply_binary("binary_little_endian", [(0, 1, 2), (0, 1, 7)]),
                                         "face 1 refers to vertex 7 but the file has 4"),
    "ply-binary-be-index-past-end.ply": (ply_binary("binary_big_endian", [(0, 1, 2), (0, 1, 7)]),
                                         "face 1 refers to vertex 7 but the file has 4"),
    "ply-binary-truncated.ply": (ply_binary("binary_little_endian", [(0, 1, 2), (0, 1, 3)], cut=5),
                                 "truncated PLY file"),
    "ply-ascii-truncated.ply": (PLY_HEAD.format(fmt="ascii", nv=4, nf=3) + PLY_V + "3 0 1 2\n",
                                "truncated PLY file"),
    "ply-ascii-short-line.ply": (PLY_HEAD.format(fmt="ascii", nv=4, nf=1) + "0 0 0\n1 0\n0 1 0\n0 0 1\n3 0 1 2\n",
                                 "vertex 1 has too few values"),
    "ply-ascii-no-final-newline.ply": (PLY_HEAD.format(fmt="ascii", nv=4, nf=1) + PLY_V + "3 0 1 2",
                                       "face 0 is not ended by a newline"),
    "ply-nan.ply": (PLY_HEAD.format(fmt="ascii", nv=4, nf=1) + "0 0 nan\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n",
                    "vertex 0 has a coordinate z that is not a finite float"),
    "ply-huge-count.ply": (PLY_HEAD.format(fmt="binary_little_endian", nv=3000000000, nf=1),
                           "3000000000 entries, over the limit of 50000000"),
    "ply-two-corner-face.ply": (PLY_HEAD.format(fmt="ascii", nv=4, nf=1) + PLY_V + "2 0 1\n",
                                "face 0 has 2 vertices"),
    "ply-unknown-type.ply": ("ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n0\n",
                             "unknown type"),
    "ply-no-y.ply": ("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float z\n"
                     "end_header\n0 0\n", "lacks one of the properties x, y, z"),
    "ply-blank-header-line.ply": (PLY_HEAD.format(fmt="ascii", nv=4, nf=1).replace("property float y\n", "\nproperty float y\n")
                                  + PLY_V + "3 0 1 2\n", "line 5: blank line in the PLY header"),
    # STL
    "stl-binary-huge-count.stl": (stl_binary(2 ** 31), "header says 2147483648 triangles but the file holds only 4"),
    "stl-binary-short.stl": (b"\xff" * 60, "shorter than the 84-byte header"),
    "stl-binary-partial.stl": (stl_binary(4, extra=b"\0" * 20), "not a whole number of 50-byte triangles"),
    "stl-binary-nan.stl": (stl_binary(4, coords=(float("nan"), 0, 0)), "triangle 2 has a vertex coordinate that is not finite"),
    "stl-binary-inf.stl": (stl_binary(4, coords=(0, float("inf"), 0)), "triangle 2 has a vertex coordinate that is not finite"),
    "stl-ascii-nan.stl": (stl_ascii(["0 0 0", "1 nan 0", "0 1 0"]), "facet 1 has a vertex coordinate that is not a finite float"),
    "stl-ascii-overflow.stl": (stl_ascii(["0 0 0", "1 0 0", "0 1 1e39"]), "not a finite float (got \"1e39\")"),
    "stl-ascii-four-vertices.stl": (stl_ascii(["0 0 0", "1 0 0", "0 1 0", "0 0 1"]), "expected \"endloop\""),
    "stl-ascii-bad-number.stl": (stl_ascii(["0 0 0", "1 zero 0", "0 1 0"]), "vertex is not 3 numbers"),
    # VTP
    "vtp-ascii-conn-past-points.vtp": (vtp_bytes("ascii", TETRA_POINTS, TETRA_CONN[:-1] + [1000], TETRA_OFFSETS),
                                       "polygon 3 refers to point 1000 but the file has 4"),
    "vtp-binary-conn-past-points.vtp": (vtp_bytes("binary", TETRA_POINTS, TETRA_CONN[:-1] + [1000], TETRA_OFFSETS),
                                        "polygon 3 refers to point 1000 but the file has 4"),
    "vtp-appended-conn-past-points.vtp": (vtp_bytes("appended", TETRA_POINTS, TETRA_CONN[:-1] + [1000], TETRA_OFFSETS),
                                          "polygon 3 refers to point 1000 but the file has 4"),
    "vtp-zlib-conn-past-points.vtp": (vtp_bytes("zlib", TETRA_POINTS, TETRA_CONN[:-1] + [1000], TETRA_OFFSETS),
                                      "polygon 3 refers to point 1000 but the file has 4"),
    "vtp-negative-id.vtp": (vtp_bytes("ascii", TETRA_POINTS, [-1] + TETRA_CONN[1:], TETRA_OFFSETS),
                            "polygon 0 refers to point -1"),
    "vtp-offsets-decreasing.vtp": (vtp_bytes("ascii", TETRA_POINTS, TETRA_CONN, [3, 6, 2, 12]),
                                   "unreadable mesh"),
    "vtp-nan-point.vtp": (vtp_bytes("ascii", TETRA_POINTS[:4] + [float("nan")] + TETRA_POINTS[5:], TETRA_CONN,
                                    TETRA_OFFSETS), "point 1 has a coordinate that is not finite"),
    "vtp-huge-count.vtp": (vtp_bytes("ascii", TETRA_POINTS, TETRA_CONN, TETRA_OFFSETS, piece_points=3000000000),
                           "NumberOfPoints adds up to 3000000000, over the limit of 50000000"),
    "vtp-not-polydata.vtp": (vtp_bytes("ascii", TETRA_POINTS, TETRA_CONN, TETRA_OFFSETS,
                                       file_type="UnstructuredGrid"), "not of type PolyData"),
    "vtp-negative-components.vtp": (vtp_bytes("appended", TETRA_POINTS, TETRA_CONN, TETRA_OFFSETS)
                                    .replace(b'NumberOfComponents="3"', b'NumberOfComponents="-1"'),
                                    "NumberOfComponents is not a count"),
    "vtp-truncated-appended.vtp": (vtp_bytes("appended", TETRA_POINTS, TETRA_CONN, TETRA_OFFSETS)[:-60],
                                   "unreadable mesh"),
}


def zlib_huge_blocks():
    data = vtp_bytes("zlib", TETRA_POINTS, TETRA_CONN, TETRA_OFFSETS)
    at = data.index(b"_", data.index(b"<AppendedData")) + 1
    return data[:at] + struct.pack("<I", 0xFFFFFFFF) + data[at + 4:]


BAD_MESHES["vtp-zlib-huge-block-count.vtp"] = (
    zlib_huge_blocks(), "DataArray 1: compressed data header is inconsistent (4294967295 blocks")

if __name__ == "__main__":
    out = os.path.join(HERE, "meshes", "bad")
    os.makedirs(out, exist_ok=True)
    for name, (data, _) in BAD_MESHES.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(data if isinstance(data, bytes) else data.encode())
    print(f"{len(BAD_MESHES)} files in {out}")
