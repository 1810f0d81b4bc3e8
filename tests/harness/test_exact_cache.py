"""exact_cache.py against a fresh computation.

    test_exact_cache.py --bin BUILD/bin --out DIR

In a cache folder of its own (DIR/cache, emptied first), on the scene of
test_soft.py at 32x24 with a made-up visibility (a ramp) and a full mask,
for exact_penumbra and exact_terminator, lights 0 and 1:

- a fresh run (the tool alone), then the same through the cache: a miss,
  then a hit; stdout byte for byte the fresh one each time, and so is
  exact_penumbra's EXACT.png; the stored field is the fresh --field-out;
- the same scene written to another path hits (the key is the content);
  another image size misses;
- a damaged entry (a byte of its field flipped; a truncated manifest) is
  reported damaged, computed again with the fresh output, and whole again
  afterwards (the next run hits).

Prints every check; exits 1 when any fails.
"""
import argparse
import os
import shutil
import struct
import sys
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import exact_cache  # noqa: E402
from soft_penumbra_common import failures, run, scene_with, verdict  # noqa: E402

TOOLS = ("exact_penumbra", "exact_terminator")


def write_png(path, w, h, value):
    """An 8-bit grey PNG with pixel (i, j) = value(i, j)."""
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))
    rows = b"".join(b"\0" + bytes(value(i, j) for i in range(w)) for j in range(h))
    with open(path, "wb") as f:
        f.write(exact_cache.PNG_SIGNATURE
                + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def images(out, w, h):
    vis, mask = (os.path.join(out, "%s_%dx%d.png" % (n, w, h)) for n in ("vis", "mask"))
    write_png(vis, w, h, lambda i, j: (7 * i + 13 * j) % 256)
    write_png(mask, w, h, lambda i, j: 255)
    return vis, mask


def read(path):
    with open(path, "rb") as f:
        return f.read()


def check(ok, what):
    print("%s: %s" % ("ok" if ok else "FAILED", what), flush=True)
    if not ok:
        failures.append(what)


def through_cache(args, tool, scene, k, vis, mask, png):
    return exact_cache.run_exact(run, args.bin, tool, scene, k, vis, mask,
                                 png if tool == "exact_penumbra" else None)


def check_tool(args, tool, scene, other_path, vis, mask):
    for k in (0, 1):
        tag = "%s light %d" % (tool, k)
        png = [os.path.join(args.out, "%s_%d_%s.png" % (tool, k, s)) for s in ("fresh", "cached")]
        field = os.path.join(args.out, "%s_%d.field" % (tool, k))
        extra = [png[0]] if tool == "exact_penumbra" else []
        fresh = run([os.path.join(args.bin, tool), scene, str(k), vis, mask] + extra)
        run([os.path.join(args.bin, tool), "--field-out", field, scene, str(k), vis, mask])
        for want in ("miss", "hit"):
            r = through_cache(args, tool, scene, k, vis, mask, png[1])
            check(r.exact_cache == want,
                  "%s: %s through the cache (got %s)" % (tag, want, r.exact_cache))
            check(r.returncode == 0 and r.stdout == fresh.stdout,
                  "%s, %s: stdout of the fresh run (%r / %r)" % (tag, want, r.stdout, fresh.stdout))
            if extra:
                check(read(png[0]) == read(png[1]), "%s, %s: EXACT.png of the fresh run" % (tag, want))
                os.unlink(png[1])
        _, stored, manifest = exact_cache.entry(args.bin, tool, scene, k, vis)
        check(os.path.exists(stored) and read(stored) == read(field),
              "%s: the stored field is the fresh --field-out" % tag)
        r = through_cache(args, tool, other_path, k, vis, mask, png[1])
        check(r.exact_cache == "hit" and r.stdout == fresh.stdout,
              "%s: the scene under another path hits, with the fresh stdout (got %s)"
              % (tag, r.exact_cache))
        for damage in ("field", "manifest"):
            if damage == "field":
                data = bytearray(read(stored))
                data[len(data) // 2] ^= 0x40
                with open(stored, "wb") as f:
                    f.write(data)
            else:
                with open(manifest, "r+b") as f:
                    f.truncate(10)
            r = through_cache(args, tool, scene, k, vis, mask, png[1])
            check(r.exact_cache == "damaged" and r.stdout == fresh.stdout,
                  "%s: a damaged %s is computed again, with the fresh stdout (got %s)"
                  % (tag, damage, r.exact_cache))
            r = through_cache(args, tool, scene, k, vis, mask, png[1])
            check(r.exact_cache == "hit" and r.stdout == fresh.stdout and read(stored) == read(field),
                  "%s: the entry is whole again after a damaged %s (got %s)"
                  % (tag, damage, r.exact_cache))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    cache = os.path.join(args.out, "cache")
    shutil.rmtree(cache, ignore_errors=True)
    os.makedirs(cache)
    os.environ["VTKSHADOW_EXACT_CACHE"] = cache
    check(exact_cache.cache_dir(args.bin) == cache, "VTKSHADOW_EXACT_CACHE names the folder")
    scene = scene_with(args.out, "scene", None)
    other = os.path.join(args.out, "elsewhere")
    os.makedirs(other, exist_ok=True)
    other_path = shutil.copy(scene, os.path.join(other, "renamed.json"))
    vis, mask = images(args.out, 32, 24)
    for tool in TOOLS:
        check_tool(args, tool, scene, other_path, vis, mask)
    vis2, mask2 = images(args.out, 24, 18)
    fresh = run([os.path.join(args.bin, "exact_penumbra"), scene, "0", vis2, mask2])
    r = exact_cache.run_exact(run, args.bin, "exact_penumbra", scene, 0, vis2, mask2)
    check(r.exact_cache == "miss" and r.stdout == fresh.stdout,
          "another image size misses, with the fresh stdout (got %s)" % r.exact_cache)
    return verdict("harness.exact_cache")


if __name__ == "__main__":
    sys.exit(main())
