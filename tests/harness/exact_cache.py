"""exact_penumbra and exact_terminator with their exact values kept by
content, so that the tests of one ctest run integrate each exact image once.

The exact values (exact_field.h) depend on the tool, the scene (and the
meshes it names), the light and the image size only, not on the render they
are compared with; the harness tests compare many renders against a
handful of exact images, each of which takes seconds to integrate. An
entry's key is the MD5 of: the tool binary's MD5, the argument list that
decides the values (the scene's and its meshes' bytes by content, not by
path, and the light) and the size of VIS. Reading an entry back gives the
tool the same doubles it would integrate, so its output is byte for byte
that of a fresh run (test_exact_cache.py checks it).

The folder: VTKSHADOW_EXACT_CACHE when set, else BUILD/test-output/exact-cache
for --bin BUILD/bin (one folder for every test of the run). An entry is
KEY.field (the tool's --field-out) and KEY.json (a manifest holding the
field's MD5 and size); both are written under a temporary name and renamed
into place, never rewritten in place, so a test running in parallel sees a
whole file or none. An entry whose field does not match its manifest is
recomputed and written again. Entries of a tool binary that has since been
rebuilt are never read again; removing the folder clears them.
"""
import hashlib
import json
import os
import struct
import tempfile

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def cache_dir(bindir):
    """VTKSHADOW_EXACT_CACHE, else BUILD/test-output/exact-cache (--bin is
    BUILD/bin, --out below BUILD/test-output: tests/vtk_tests.cmake)."""
    return os.environ.get("VTKSHADOW_EXACT_CACHE") or os.path.join(
        os.path.dirname(os.path.abspath(bindir)), "test-output", "exact-cache")


def file_md5(path):
    h = hashlib.md5()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def png_size(path):
    """[width, height] from a PNG's header."""
    with open(path, "rb") as f:
        head = f.read(24)
    if len(head) < 24 or head[:8] != PNG_SIGNATURE or head[12:16] != b"IHDR":
        raise ValueError("%s: not a PNG file" % path)
    return list(struct.unpack(">II", head[16:24]))


def scene_content(scene):
    """The scene by content: its bytes' MD5 and, per mesh it names, the name
    as written and the MD5 of the file the scene loader reads (relative
    names from the scene's folder; None when unreadable)."""
    with open(scene, "rb") as f:
        data = f.read()
    meshes = []
    try:
        objects = json.loads(data).get("objects", [])
    except (ValueError, AttributeError):
        objects = []
    for o in objects if isinstance(objects, list) else []:
        mesh = o.get("mesh") if isinstance(o, dict) else None
        if isinstance(mesh, str):
            path = os.path.join(os.path.dirname(scene), mesh)
            try:
                meshes.append([mesh, file_md5(path)])
            except OSError:
                meshes.append([mesh, None])
    return {"md5": hashlib.md5(data).hexdigest(), "meshes": meshes}


def entry(bindir, tool, scene, light, vis):
    """(inputs, KEY.field, KEY.json): everything the exact values depend on,
    and the entry's files, KEY being the inputs' MD5."""
    inputs = {"tool": tool, "binary_md5": file_md5(os.path.join(bindir, tool)),
              "args": [scene_content(scene), str(light)], "size": png_size(vis)}
    key = "%s-%s" % (tool, hashlib.md5(json.dumps(inputs, sort_keys=True).encode()).hexdigest())
    stem = os.path.join(cache_dir(bindir), key)
    return inputs, stem + ".field", stem + ".json"


def entry_state(field, manifest):
    """"hit" (the field matches its manifest), "miss" (no manifest) or
    "damaged"."""
    try:
        with open(manifest) as f:
            m = json.load(f)
    except FileNotFoundError:
        return "miss"
    except (OSError, ValueError):
        return "damaged"
    try:
        whole = os.path.getsize(field) == m["bytes"] and file_md5(field) == m["field_md5"]
    except (OSError, KeyError, TypeError):
        whole = False
    return "hit" if whole else "damaged"


def replace_with(path, data, folder):
    """Writes data to a temporary file in folder, then renames it to path."""
    fd, tmp = tempfile.mkstemp(prefix=".tmp-", dir=folder)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except OSError:
        os.unlink(tmp)
        raise


def store(tmp_field, field, manifest, inputs, folder):
    """Moves a fresh --field-out into place, then its manifest."""
    with open(tmp_field, "rb") as f:
        data = f.read()
    os.replace(tmp_field, field)
    replace_with(manifest, json.dumps({"field_md5": hashlib.md5(data).hexdigest(),
                                       "bytes": len(data), "inputs": inputs},
                                      indent=1, sort_keys=True).encode(), folder)


def run_exact(run, bindir, tool, scene, light, vis, mask, exact_png=None):
    """BINDIR/TOOL SCENE LIGHT VIS MASK [EXACT_PNG], run by `run` (the
    test's runner: it prints the command and records a failure; it returns
    the subprocess.CompletedProcess) with the exact values from the cache
    (--field-in) or, when they are not there, integrated and stored
    (--field-out). The result's `exact_cache` is "hit", "miss", "damaged"
    (an entry failed its check and was recomputed) or "off" (no key: an
    input is unreadable, or no cache folder; the tool runs as it is and
    reports the problem itself)."""
    binary = os.path.join(bindir, tool)
    args = [scene, str(light), vis, mask] + ([exact_png] if exact_png else [])
    folder = cache_dir(bindir)
    try:
        inputs, field, manifest = entry(bindir, tool, scene, light, vis)
        state = entry_state(field, manifest)
        if state != "hit":
            os.makedirs(folder, exist_ok=True)
            fd, tmp = tempfile.mkstemp(prefix=".tmp-", suffix=".field", dir=folder)
            os.close(fd)
    except (OSError, ValueError) as e:
        print("exact cache off for %s: %s" % (tool, e), flush=True)
        r = run([binary] + args)
        r.exact_cache = "off"
        return r
    if state == "hit":
        r = run([binary, "--field-in", field] + args)
        r.exact_cache = state
        return r
    if state == "damaged":
        print("exact cache: %s is damaged, computing it again" % field, flush=True)
    try:
        r = run([binary, "--field-out", tmp] + args)
        if r.returncode == 0:
            try:
                store(tmp, field, manifest, inputs, folder)
            except OSError as e:
                print("exact cache: %s not stored: %s" % (field, e), flush=True)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)
    r.exact_cache = state
    return r
