#!/usr/bin/env python3
"""Writes the seed corpus of the mesh checkers' fuzz tests (tests/mesh/corpus),
small good files of every format and encoding the scene format accepts:
OBJ, PLY (ASCII, binary little and big endian), STL (ASCII, binary) and VTP
(ASCII, inline base64, appended raw, appended zlib-compressed). Pure Python,
so the files do not come from the code under test. Run from anywhere:
    python3 tests/mesh/make_corpus.py"""
import base64
import os
import struct
import zlib

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
# A tetrahedron, counter-clockwise seen from outside.
PTS = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
TRIS = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def write(rel, data):
    path = os.path.join(HERE, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def obj():
    write("obj/tetra.obj", "# tetrahedron\n" + "".join(f"v {x} {y} {z}\n" for x, y, z in PTS) +
          "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in TRIS))
    # A cube with quads, texture coordinates, normals, groups, relative indices.
    cube = ["mtllib none.mtl", "o cube", "g sides"]
    cube += [f"v {x} {y} {z}" for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    cube += ["vt 0 0", "vt 1 0", "vt 1 1", "vt 0 1", "vn 0 0 1", "usemtl none", "s off"]
    quads = [(1, 3, 4, 2), (5, 6, 8, 7), (1, 2, 6, 5), (3, 7, 8, 4), (1, 5, 7, 3), (2, 4, 8, 6)]
    for i, q in enumerate(quads):
        if i % 3 == 0:
            cube.append("f " + " ".join(f"{v}/{k + 1}/1" for k, v in enumerate(q)))
        elif i % 3 == 1:
            cube.append("f " + " ".join(f"{v}//1" for v in q))
        else:
            cube.append("f " + " ".join(f"{v - 9}/{k - 4}" for k, v in enumerate(q)))
    cube += ["l 1 2", "p 3"]
    write("obj/cube.obj", "\n".join(cube) + "\n")


def ply():
    head = ("ply\nformat {fmt} 1.0\ncomment tetrahedron\nelement vertex 4\n"
            "property float x\nproperty float y\nproperty float z\nproperty uchar red\n"
            "element face 4\nproperty list uchar int vertex_indices\nend_header\n")
    body = "".join(f"{x} {y} {z} 200\n" for x, y, z in PTS)
    body += "".join(f"3 {a} {b} {c}\n" for a, b, c in TRIS)
    write("ply/tetra-ascii.ply", head.format(fmt="ascii") + body)
    for fmt, e in (("binary_little_endian", "<"), ("binary_big_endian", ">")):
        data = b"".join(struct.pack(e + "fffB", *p, 200) for p in PTS)
        data += b"".join(struct.pack(e + "B3i", 3, *t) for t in TRIS)
        write(f"ply/tetra-{fmt}.ply", head.format(fmt=fmt).encode() + data)
    # Texture coordinates per face corner and a double-precision vertex.
    head = ("ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty double x\n"
            "property double y\nproperty double z\nelement face 4\n"
            "property list uchar uint vertex_indices\nproperty list uchar float texcoord\n"
            "end_header\n")
    data = b"".join(struct.pack("<ddd", *p) for p in PTS)
    data += b"".join(struct.pack("<B3IB6f", 3, *t, 6, 0, 0, 1, 0, 0, 1) for t in TRIS)
    write("ply/tetra-texcoord.ply", head.encode() + data)


def stl():
    def normal(t):
        a, b, c = (PTS[i] for i in t)
        u = [b[k] - a[k] for k in range(3)]
        v = [c[k] - a[k] for k in range(3)]
        return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    text = "solid tetra\n"
    for t in TRIS:
        text += " facet normal %g %g %g\n  outer loop\n" % normal(t)
        text += "".join("   vertex %g %g %g\n" % PTS[i] for i in t)
        text += "  endloop\n endfacet\n"
    write("stl/tetra-ascii.stl", text + "endsolid tetra\n")
    data = b"binary tetrahedron".ljust(80, b"\0") + struct.pack("<I", len(TRIS))
    for t in TRIS:
        data += struct.pack("<3f", *normal(t))
        data += b"".join(struct.pack("<3f", *PTS[i]) for i in t) + b"\0\0"
    write("stl/tetra-binary.stl", data)


def vtp_bytes(encoding, points, conn, offsets, piece_points=None, file_type="PolyData",
              point_type="Float32"):
    """A VTP file with one Piece of polygons; encoding: ascii, binary (inline
    base64), appended (raw) or zlib (appended, compressed). Values are written
    as given, so callers can make them inconsistent on purpose."""
    pfmt = "<%d%s" % (len(points), "f" if point_type == "Float32" else "d")
    arrays = [(point_type, 'NumberOfComponents="3"', "Points", struct.pack(pfmt, *points), points),
              ("Int32", 'Name="connectivity"', "Polys", struct.pack("<%di" % len(conn), *conn), conn),
              ("Int32", 'Name="offsets"', "Polys", struct.pack("<%di" % len(offsets), *offsets),
               offsets)]
    npts = len(points) // 3 if piece_points is None else piece_points
    body, group, appended, offset = "", None, b"", 0
    for typ, attr, grp, raw, values in arrays:
        if grp != group:
            body += (f"</{group}>\n" if group else "") + f"<{grp}>\n"
            group = grp
        if encoding == "ascii":
            text = " ".join(f"{v:g}" if isinstance(v, float) else str(v) for v in values)
            body += f'<DataArray type="{typ}" {attr} format="ascii">{text}</DataArray>\n'
        elif encoding == "binary":
            text = base64.b64encode(struct.pack("<I", len(raw)) + raw).decode()
            body += f'<DataArray type="{typ}" {attr} format="binary">{text}</DataArray>\n'
        else:
            if encoding == "zlib":
                z = zlib.compress(raw)
                chunk = struct.pack("<4I", 1, len(raw), len(raw), len(z)) + z  # one block
            else:
                chunk = struct.pack("<I", len(raw)) + raw
            body += (f'<DataArray type="{typ}" {attr} format="appended" offset="{offset}">'
                     "</DataArray>\n")
            offset += len(chunk)
            appended += chunk
    body += f"</{group}>\n"
    extra = ' compressor="vtkZLibDataCompressor"' if encoding == "zlib" else ""
    out = ('<?xml version="1.0"?>\n'
           f'<VTKFile type="{file_type}" version="1.0" byte_order="LittleEndian" '
           f'header_type="UInt32"{extra}>\n<{file_type}>\n'
           f'<Piece NumberOfPoints="{npts}" NumberOfVerts="0" NumberOfLines="0" '
           f'NumberOfStrips="0" NumberOfPolys="{len(offsets)}">\n'
           + body + f"</Piece>\n</{file_type}>\n").encode()
    if appended:
        out += b'<AppendedData encoding="raw">\n_' + appended + b"\n</AppendedData>\n"
    return out + b"</VTKFile>\n"


TETRA_POINTS = [c for p in PTS for c in p]
TETRA_CONN = [i for t in TRIS for i in t]
TETRA_OFFSETS = [3, 6, 9, 12]


def vtp():
    for encoding in ("ascii", "binary", "appended", "zlib"):
        write(f"vtp/tetra-{encoding}.vtp",
              vtp_bytes(encoding, TETRA_POINTS, TETRA_CONN, TETRA_OFFSETS))
    write("vtp/tetra-double.vtp", vtp_bytes("appended", TETRA_POINTS, TETRA_CONN, TETRA_OFFSETS,
                                            point_type="Float64"))


if __name__ == "__main__":
    obj()
    ply()
    stl()
    vtp()
