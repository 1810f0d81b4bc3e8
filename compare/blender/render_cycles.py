# render_cycles.py - the ONE fixed Blender script of the vtkshadow harness,
# for Cycles (the check of the POV-Ray reference) and for EEVEE (a peer
# rasterizer measured like the VTK techniques; docs/harness.md).
#
#   blender -b --factory-startup --python-exit-code 1 -t N \
#       --python compare/blender/render_cycles.py -- DATAFILE OUTDIR [PRESET]
#
# PRESET is one of the fixed words `cycles` (default), `eevee` (Blender's own
# EEVEE shadow defaults) or `eevee-best` (EEVEE shadow settings chosen for
# hard shadows); see PRESETS below. EEVEE needs an X display (xvfb-run -a).
# `cycles-color` renders the colour image of a scene with planar mirrors
# instead (docs/reflections.md): every light at once, shadows on, objects in
# their colours, a mirror of reflectance R = a mix (factor R) of its Diffuse
# BSDF and a sharp white Glossy BSDF (no fresnel), one glossy bounce, lights
# scaled to POV-Ray's units (no distance falloff, a white surface facing
# the light shows 1); it writes OUTDIR/color.f32 (R, G, B per pixel,
# float32, BOTTOM row first).
#
# DATAFILE is a binary file of numbers written by vtkshadow-compare (format
# below); nothing in it is ever evaluated, so a scene file cannot run code
# through Blender. For every light K the script renders the scene twice with
# only that light (shadows on, shadows off) and writes
#   OUTDIR/light<K>_on.f32, OUTDIR/light<K>_off.f32
# as raw little-endian float32, width*height values of the red channel,
# BOTTOM row first (Blender's order); the harness flips the rows. A tinted
# scene (an object with opacity < 1 and filter > 0) also gets the green and
# blue channels, light<K>_on_g.f32, light<K>_on_b.f32, light<K>_off_g.f32
# and light<K>_off_b.f32 (the same renders). It also
# writes OUTDIR/frame_seconds.txt: one line per render (light, on|off,
# seconds of bpy.ops.render.render, i.e. one frame without Blender start-up).
#
# DATAFILE layout (little-endian):
#   8 bytes   magic b"VSHCYC04"
#   int32 x7  width, height, samples (Cycles only), seed (Cycles only),
#             pixel_centre (1: Gaussian filter 0.01, every sample at the pixel
#             centre; 0: BOX filter 1.0 over the pixel), light_count, object_count
#   float64 x10 camera: eye[3], focal[3], up[3], vertical view angle (deg)
#   float64 x2  clip_start, clip_end
#   per light:  float64 x9  type (0 dir, 1 point, 2 spot), position[3],
#               axis[3] (unit; where the light travels / cone axis), cone half-angle (deg),
#               size (point, spot: disk radius, Blender's shadow_soft_size;
#               directional: angular diameter in degrees, Blender's sun angle; 0 hard)
#   per object: int32 x3  point_count, triangle_count, casts
#               float64 x4  colour (linear R, G, B), mirror reflectance (0: none)
#               float64 x2  opacity, filter (docs/translucency.md)
#               float64 x 3*point_count  points
#               float64 x 3*point_count  normals
#               int32   x 3*triangle_count  triangles
#   optional trailer (scenes with volumes only): 4 bytes b"VOLS", int32 count,
#   per volume: float64 x5  centre[3], radius, density; int32 casts. The
#               extinction density * max(0, 1 - |p - centre| / radius) per
#               unit length (docs/scene-format.md, "volume").
import math
import os
import struct
import sys
import time
from array import array

import bpy
from mathutils import Matrix, Vector


def fail(message):
    sys.stderr.write("render_cycles.py: %s\n" % message)
    sys.exit(1)


def read_data(path):
    with open(path, "rb") as f:
        data = f.read()
    pos = 0

    def take(fmt):
        nonlocal pos
        size = struct.calcsize(fmt)
        if pos + size > len(data):
            fail("%s: truncated" % path)
        values = struct.unpack_from(fmt, data, pos)
        pos += size
        return values

    def take_array(code, count):
        nonlocal pos
        a = array(code)
        size = a.itemsize * count
        if pos + size > len(data):
            fail("%s: truncated" % path)
        a.frombytes(data[pos:pos + size])
        if sys.byteorder != "little":
            a.byteswap()
        pos += size
        return a

    if take("<8s")[0] != b"VSHCYC04":
        fail("%s: not a vtkshadow Cycles data file (version 04)" % path)
    width, height, samples, seed, centre, nlights, nobjects = take("<7i")
    camera = take("<10d")
    clip = take("<2d")
    lights = [take("<9d") for _ in range(nlights)]
    for light in lights:
        if not (math.isfinite(light[8]) and light[8] >= 0.0 and (light[0] != 0 or light[8] < 180.0)):
            fail("%s: bad light size %r" % (path, light[8]))
    objects = []
    for _ in range(nobjects):
        npts, ntri, casts = take("<3i")
        colour = take("<4d")
        opacity, filt = take("<2d")
        if not (0.0 <= opacity <= 1.0 and 0.0 <= filt <= 1.0):
            fail("%s: bad opacity %r or filter %r" % (path, opacity, filt))
        pts = take_array("d", 3 * npts)
        nrm = take_array("d", 3 * npts)
        tri = take_array("i", 3 * ntri)
        objects.append((npts, ntri, casts, pts, nrm, tri, colour, (opacity, filt)))
    volumes = []
    if pos < len(data) and take("<4s")[0] == b"VOLS":
        for _ in range(take("<i")[0]):
            volume = take("<5d") + take("<i")
            if not (volume[3] > 0.0 and volume[4] > 0.0 and all(map(math.isfinite, volume))):
                fail("%s: bad volume %r" % (path, volume))
            volumes.append(volume)
    if pos != len(data):
        fail("%s: trailing bytes" % path)
    return width, height, (samples, seed, centre), camera, clip, lights, objects, volumes


def frame_from_axis(z_axis):
    """A rotation whose local -Z is `axis` (lights shine down local -Z)."""
    z = -Vector(z_axis).normalized()
    helper = Vector((1.0, 0.0, 0.0)) if abs(z.x) < 0.9 else Vector((0.0, 1.0, 0.0))
    x = helper.cross(z).normalized()
    y = z.cross(x)
    return Matrix(((x.x, y.x, z.x), (x.y, y.y, z.y), (x.z, y.z, z.z)))


# EEVEE shadow settings of the two presets (docs/harness.md, "EEVEE as a peer").
# `eevee` sets nothing here: scene.eevee and every light keep the values
# Blender gives a new scene / a newly created light (cascade 1024, cube 512,
# soft shadows on, 16-bit maps, light radius 0.25, sun angle 0.526 deg,
# bias 1.0, 4 cascades up to 200 units, exponent 0.8, 64 TAA samples).
# `eevee-best` is for the hard point / directional / spot shadows of the
# references: largest maps, 32-bit depth, no soft shadows (radius 0, angle 0),
# cascades fitted to the visible depth, the lowest bias that stays clean.
# Bias: measured 0.05 / 0.2 / 0.5 on hard/small-caster-big-floor and
# scivis/isosurface at --scale 0.5: lower bias leaks less light at contacts
# (isosurface wrong_pct 0.45 / 0.48 / 0.54 for the sun) and only adds a few
# false-shadow pixels; 0.1 keeps a factor 2 from the lowest value tried.
# Cascade exponent: with the near plane fitted to the geometry the depth
# range is short (far/near ~ 3-10), so an even mix of uniform and logarithmic
# splits; 0.8 (Blender's) gave the same within 0.03 points (better on one
# scene, worse on the other).
EEVEE_BEST = {
    "shadow_cascade_size": "4096",
    "shadow_cube_size": "4096",
    "use_shadow_high_bitdepth": True,
    "use_soft_shadows": False,
}
EEVEE_BEST_BIAS = 0.1
EEVEE_BEST_CASCADE_EXPONENT = 0.5
PRESETS = ("cycles", "eevee", "eevee-best", "cycles-color")
# Samples of the colour render: the mix of diffuse and glossy is sampled one
# closure per path, so the reflection needs many samples per pixel centre.
COLOR_SAMPLES = 256


def setup_cycles(scene, sampling):
    samples, seed, centre = sampling
    scene.render.engine = "CYCLES"
    cyc = scene.cycles
    cyc.device = "CPU"
    cyc.samples = samples
    cyc.use_adaptive_sampling = False
    cyc.use_denoising = False
    cyc.max_bounces = 0
    cyc.diffuse_bounces = 0
    cyc.glossy_bounces = 0
    cyc.transmission_bounces = 0
    cyc.volume_bounces = 0
    # Shadow rays pass through translucent objects (their Transparent BSDF):
    # 64 crossings, far more than any scene's nested shells. Opaque scenes
    # have no Transparent BSDF, so this changes nothing for them.
    cyc.transparent_max_bounces = 64
    cyc.caustics_reflective = False
    cyc.caustics_refractive = False
    cyc.light_sampling_threshold = 0.0
    # One seed for the shadows-on and shadows-off renders: the same light
    # samples, so their ratio is the unoccluded fraction of the same points.
    cyc.seed = seed
    cyc.use_animated_seed = False
    # Every sample at the pixel centre: a Gaussian of width 0.01 (samples
    # within +-0.005 px). Not BOX: Blender's sync gives a BOX filter width
    # 1.0 whatever filter_width says, which spread the soft-light samples
    # over the whole pixel (a hard sun's edge came out grey, a 1-px penumbra
    # blurred; docs/harness.md, "Lights with a size"). Over the pixel: BOX.
    cyc.pixel_filter_type = "GAUSSIAN" if centre else "BOX"
    cyc.filter_width = 0.01 if centre else 1.0


def setup_eevee(scene, best):
    scene.render.engine = "BLENDER_EEVEE"
    # Pixel-centre sampling like the ray tracers (a film setting, not a
    # shadow one): the TAA samples are not spread over the pixel.
    scene.render.filter_size = 0.0
    ee = scene.eevee
    # No screen-space effects that would change I_on / I_off (all off by default).
    for prop in ("use_gtao", "use_ssr", "use_bloom", "use_motion_blur", "use_volumetric_lights"):
        if hasattr(ee, prop):
            setattr(ee, prop, False)
    if best:
        for prop, value in EEVEE_BEST.items():
            setattr(ee, prop, value)


def visible_depth(camera, clip, objects):
    """Nearest and farthest depth (along the view direction) of the
    geometry in front of the camera, clamped to the exported clip range."""
    eye = Vector(camera[0:3])
    f = (Vector(camera[3:6]) - eye).normalized()
    near, far = clip[1], clip[0]
    for (npts, _ntri, _casts, pts, _nrm, _tri, _colour, _translucency) in objects:
        for i in range(npts):
            d = (pts[3 * i] - eye.x) * f.x + (pts[3 * i + 1] - eye.y) * f.y + (pts[3 * i + 2] - eye.z) * f.z
            if d > clip[0]:
                near = min(near, d)
                far = max(far, d)
    if far <= near:
        return clip[0], clip[1]
    return max(clip[0], near), min(clip[1], far)


def farthest_point(position, objects):
    p = Vector(position)
    best = 0.0
    for (npts, _ntri, _casts, pts, _nrm, _tri, _colour, _translucency) in objects:
        for i in range(npts):
            best = max(best, (Vector(pts[3 * i:3 * i + 3]) - p).length)
    return best


def new_lambert_material(name, rgb):
    """A new material whose node tree holds only a Lambertian Diffuse BSDF
    (roughness 0) of colour `rgb`: (material, nodes, links, diffuse)."""
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes = mat.node_tree.nodes
    nodes.clear()
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = tuple(rgb) + (1.0,)
    diffuse.inputs["Roughness"].default_value = 0.0
    return mat, nodes, mat.node_tree.links, diffuse


def make_colour_material(name, colour):
    """POV-Ray's finish { diffuse 1-R reflection { R } } with pigment c:
    (1-R) Lambert(c) + R perfect mirror (white, no fresnel)."""
    (r, g, b, mirror) = colour
    mat, nodes, links, diffuse = new_lambert_material(name, (r, g, b))
    out = nodes.new("ShaderNodeOutputMaterial")
    if mirror <= 0:
        links.new(diffuse.outputs["BSDF"], out.inputs["Surface"])
        return mat
    glossy = nodes.new("ShaderNodeBsdfGlossy")
    glossy.distribution = "SHARP"
    glossy.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    glossy.inputs["Roughness"].default_value = 0.0
    mix = nodes.new("ShaderNodeMixShader")
    mix.inputs["Fac"].default_value = mirror
    links.new(diffuse.outputs["BSDF"], mix.inputs[1])
    links.new(glossy.outputs["BSDF"], mix.inputs[2])
    links.new(mix.outputs["Shader"], out.inputs["Surface"])
    return mat


def colour_light(ldata, ltype):
    """POV-Ray's light units: no distance falloff and a white Lambertian
    surface facing the light at value 1. Cycles divides a sun's strength by
    nothing and a Lambert BSDF gives albedo/pi, so the sun gets pi; a point
    or spot light of power P has intensity P/(4 pi), and the Light Falloff
    node's Constant output removes the 1/d^2, so P = 4 pi^2."""
    ldata.energy = math.pi if ltype == 0 else 4.0 * math.pi * math.pi
    if ltype == 0:
        return
    ldata.use_nodes = True
    nodes = ldata.node_tree.nodes
    emission = next(n for n in nodes if n.type == "EMISSION")
    falloff = nodes.new("ShaderNodeLightFalloff")
    falloff.inputs["Strength"].default_value = 1.0
    ldata.node_tree.links.new(falloff.outputs["Constant"], emission.inputs["Strength"])


def make_translucent_material(name, colour, translucency):
    """A translucent object (docs/translucency.md): a shadow ray crossing
    it keeps (1 - a) ((1 - f) + f c) of the light, POV-Ray's rgbft. The
    Transparent BSDF's colour is (1 - f) + f c, its weight in the mix
    1 - a; the rest is Lambertian in the object's colour (the camera does
    not see it in the visibility renders)."""
    (r, g, b, _) = colour
    opacity, filt = translucency
    mat, nodes, links, diffuse = new_lambert_material(name, (r, g, b))
    clear = nodes.new("ShaderNodeBsdfTransparent")
    clear.inputs["Color"].default_value = tuple((1.0 - filt) + filt * c for c in (r, g, b)) + (1.0,)
    mix = nodes.new("ShaderNodeMixShader")
    mix.inputs["Fac"].default_value = 1.0 - opacity
    links.new(diffuse.outputs["BSDF"], mix.inputs[1])
    links.new(clear.outputs["BSDF"], mix.inputs[2])
    out = nodes.new("ShaderNodeOutputMaterial")
    links.new(mix.outputs["Shader"], out.inputs["Surface"])
    mat.blend_method = "BLEND"  # EEVEE draws it see-through as well
    return mat


def make_material(name, preset, casts):
    # White Lambertian: a Diffuse BSDF (roughness 0 = Lambert), colour 1.
    mat, nodes, links, bsdf = new_lambert_material(name, (1.0, 1.0, 1.0))
    out = nodes.new("ShaderNodeOutputMaterial")
    links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    if preset != "cycles" and not casts:
        mat.shadow_method = "NONE"  # EEVEE: objects with "casts": false
    return mat


def make_light(ltype, cone, size, preset, position, objects, depth):
    kind = ("SUN", "POINT", "SPOT")[ltype]
    ldata = bpy.data.lights.new("light", kind)
    if ltype == 2:
        ldata.spot_size = math.radians(2.0 * cone)
        ldata.spot_blend = 0.0
        ldata.show_cone = False
    ldata.energy = 1.0
    ldata.color = (1.0, 1.0, 1.0)
    if preset == "cycles":
        # The scene's size: Cycles 3.4 samples a point or spot light as a disk
        # of radius shadow_soft_size facing the shaded point, a sun within
        # `angle` (angular diameter); 0 is a hard light.
        if ltype == 0:
            ldata.angle = math.radians(size)
        else:
            ldata.shadow_soft_size = size
        ldata.cycles.max_bounces = 0
        return ldata
    if size > 0.0:
        # A light with a size is the scene's light: EEVEE gets it too, with
        # its soft shadows on (both presets).
        bpy.context.scene.eevee.use_soft_shadows = True
    if ltype != 0:
        # The light reaches the whole scene (EEVEE otherwise cuts it off where
        # energy/distance^2 < light_threshold); also the far plane of its
        # shadow map, so it is fitted, not huge.
        ldata.use_custom_distance = True
        ldata.cutoff_distance = 1.01 * farthest_point(position, objects) + 1e-6
    if preset == "eevee-best":
        ldata.shadow_buffer_bias = EEVEE_BEST_BIAS
        if ltype == 0:
            ldata.angle = math.radians(size)
            ldata.shadow_cascade_count = 4
            ldata.shadow_cascade_max_distance = 1.01 * depth[1]
            ldata.shadow_cascade_exponent = EEVEE_BEST_CASCADE_EXPONENT
        else:
            ldata.shadow_soft_size = size
    elif size > 0.0:
        if ltype == 0:
            ldata.angle = math.radians(size)
        else:
            ldata.shadow_soft_size = size
    return ldata


def set_shadows(ldata, preset, on):
    if preset == "cycles":
        ldata.cycles.cast_shadow = on
    else:
        ldata.use_shadow = on


def place_light(scene, ldata, light):
    (_ltype, px, py, pz, ax, ay, az, _cone, _size) = light
    lobj = bpy.data.objects.new("light", ldata)
    rot = frame_from_axis((ax, ay, az)).to_4x4()
    rot.translation = Vector((px, py, pz))
    lobj.matrix_world = rot
    scene.collection.objects.link(lobj)
    return lobj


def render_pixels(scene, exr, width, height):
    """One bpy.ops.render.render into `exr`, read back: (image, RGBA floats,
    bottom row first) and the seconds of the render alone."""
    scene.render.filepath = exr
    start = time.monotonic()
    bpy.ops.render.render(write_still=True)
    seconds = time.monotonic() - start
    img = bpy.data.images.load(exr, check_existing=False)
    if tuple(img.size) != (width, height):
        fail("rendered %dx%d, expected %dx%d" % (img.size[0], img.size[1], width, height))
    px4 = array("f", bytes(4 * 4 * width * height))
    img.pixels.foreach_get(px4)
    return img, px4, seconds


def write_floats(target, values):
    """`values` (an array of float32) as raw little-endian floats, atomically."""
    with open(target + ".tmp", "wb") as f:
        if sys.byteorder != "little":
            values.byteswap()
        values.tofile(f)
    os.replace(target + ".tmp", target)


def remove_quietly(path):
    try:
        os.remove(path)
    except OSError:
        pass


def render_colour(scene, lights, objects, depth, exr, outdir, width, height):
    """cycles-color: every light at once, shadows on; color.f32 = RGB."""
    for light in lights:
        (ltype, px, py, pz, _ax, _ay, _az, cone, size) = light
        # The light's size too: POV-Ray's colour scene makes it an area light.
        ldata = make_light(int(ltype), cone, size, "cycles", (px, py, pz), objects, depth)
        ldata.cycles.max_bounces = 1
        colour_light(ldata, int(ltype))
        set_shadows(ldata, "cycles", True)
        place_light(scene, ldata, light)
    _img, px4, _seconds = render_pixels(scene, exr, width, height)
    rgb = array("f", bytes(4 * 3 * width * height))
    for c in range(3):
        rgb[c::3] = px4[c::4]
    write_floats(os.path.join(outdir, "color.f32"), rgb)
    remove_quietly(exr)
    sys.stderr.write("cycles-color: done\n")


def render_lights(scene, lights, objects, depth, preset, exr, outdir, width, height):
    """Each light alone, shadows on then off: light<K>_on.f32 and
    light<K>_off.f32 (red channel; a tinted scene's green and blue as
    light<K>_on_g.f32 ... too) and frame_seconds.txt."""
    tinted = any(obj[7][0] < 1.0 and obj[7][1] > 0.0 for obj in objects)
    channels = (("", 0), ("_g", 1), ("_b", 2)) if tinted else (("", 0),)
    frame_log = []
    for k, light in enumerate(lights):
        (ltype, px, py, pz, _ax, _ay, _az, cone, size) = light
        ldata = make_light(int(ltype), cone, size, preset, (px, py, pz), objects, depth)
        lobj = place_light(scene, ldata, light)
        for state in ("on", "off"):
            set_shadows(ldata, preset, state == "on")
            img, px4, seconds = render_pixels(scene, exr, width, height)
            frame_log.append("%d %s %.4f\n" % (k, state, seconds))
            for suffix, c in channels:
                name = "light%d_%s%s.f32" % (k, state, suffix)
                write_floats(os.path.join(outdir, name), px4[c::4])
            bpy.data.images.remove(img)
            sys.stderr.write("%s: light %d shadows %s done\n" % (preset, k, state))
        bpy.data.objects.remove(lobj, do_unlink=True)
        bpy.data.lights.remove(ldata)
    with open(os.path.join(outdir, "frame_seconds.txt"), "w") as f:
        f.writelines(frame_log)
    remove_quietly(exr)


def parse_arguments():
    """(datafile, outdir, preset, colour): `cycles-color` is the cycles preset
    with colour set."""
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(argv) not in (2, 3) or (len(argv) == 3 and argv[2] not in PRESETS):
        fail("usage: blender -b --factory-startup --python-exit-code 1 --python render_cycles.py "
             "-- DATAFILE OUTDIR [%s]" % "|".join(PRESETS))
    preset = argv[2] if len(argv) == 3 else "cycles"
    colour = preset == "cycles-color"
    if colour:
        preset = "cycles"  # the same renderer settings, then the colour changes
    return argv[0], argv[1], preset, colour


def empty_scene():
    """The factory scene without its cube, light, camera and world."""
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    scene = bpy.context.scene
    scene.world = None
    return scene


def setup_renderer(scene, preset, colour, samples, camera, clip, objects):
    """The preset's renderer settings; returns the camera's depth range."""
    if preset == "cycles":
        setup_cycles(scene, samples)
        if colour:
            # Pixel centre like POV-Ray -A; one bounce: the mirror's reflection.
            scene.cycles.filter_width = 0.01
            scene.cycles.max_bounces = 1
            scene.cycles.glossy_bounces = 1
        return clip
    setup_eevee(scene, preset == "eevee-best")
    # A rasterizer needs a depth range fitted to the scene (as VTK's
    # ResetCameraClippingRange); the ray tracers' 1e-5 near plane would
    # waste the depth buffer and the cascades. Same for both presets.
    near, far = visible_depth(camera, clip, objects)
    return (0.5 * near, 1.01 * far)


def setup_output(scene, width, height):
    """The image: its size, no colour management, 32-bit EXR."""
    scene.render.resolution_x = width
    scene.render.resolution_y = height
    scene.render.resolution_percentage = 100
    scene.render.pixel_aspect_x = 1.0
    scene.render.pixel_aspect_y = 1.0
    scene.render.dither_intensity = 0.0
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.exr_codec = "NONE"
    scene.render.use_compositing = False
    scene.render.use_sequencer = False


def add_mesh(scene, index, obj_data, preset, colour, materials):
    """One object of the data file as a Blender mesh object, with the
    loader's normals and its material."""
    (npts, ntri, casts, pts, nrm, tri, rgbm, translucency) = obj_data
    mesh = bpy.data.meshes.new("m%d" % index)
    mesh.vertices.add(npts)
    mesh.vertices.foreach_set("co", array("f", pts))
    mesh.loops.add(3 * ntri)
    mesh.loops.foreach_set("vertex_index", tri)
    mesh.polygons.add(ntri)
    mesh.polygons.foreach_set("loop_start", array("i", range(0, 3 * ntri, 3)))
    mesh.polygons.foreach_set("loop_total", array("i", [3]) * ntri)
    mesh.polygons.foreach_set("use_smooth", array("b", [1]) * ntri)
    mesh.update(calc_edges=True)
    mesh.validate(clean_customdata=False)
    # The loader's per-vertex normals, exactly (custom split normals).
    mesh.use_auto_smooth = True
    mesh.normals_split_custom_set_from_vertices(
        [tuple(nrm[3 * i:3 * i + 3]) for i in range(npts)])
    translucent = translucency[0] < 1.0
    if translucent:
        mesh.materials.append(make_translucent_material("t%d" % index, rgbm, translucency))
    elif colour:
        mesh.materials.append(make_colour_material("c%d" % index, rgbm))
    else:
        if bool(casts) not in materials:
            materials[bool(casts)] = make_material("white%d" % casts, preset, casts)
        mesh.materials.append(materials[bool(casts)])
    obj = bpy.data.objects.new("o%d" % index, mesh)
    obj.visible_shadow = bool(casts)
    # The visibility renders measure the opaque surface behind a translucent
    # object (POV-Ray's no_image; vtkShadowScene draws it black).
    obj.visible_camera = not (translucent and not colour)
    # No shadow-terminator tricks: shadow rays start on the true triangle.
    # (Blender 3.4 keeps these on the object's Cycles settings.)
    for holder in (obj, obj.cycles):
        for prop in ("shadow_terminator_geometry_offset", "shadow_terminator_offset",
                     "shadow_terminator_normal_offset"):
            if hasattr(holder, prop):
                setattr(holder, prop, 0.0)
    scene.collection.objects.link(obj)


def add_volume(scene, index, volume):
    """A volume (harness_export.h ExportVolume): a closed sphere slightly
    larger than the density's support, with no surface shader (shadow rays
    cross its boundary) and a Volume Absorption of colour 0, whose
    extinction is its density (Cycles absorbs density * (1 - colour)):
    density * max(0, 1 - |p - centre| / radius) from the world position.
    The camera does not see it (POV-Ray's no_image; vtkShadowScene draws it
    black in the visibility renders)."""
    cx, cy, cz, radius, density, casts = volume
    nlon, nlat, r = 64, 32, 1.01 * radius
    verts = [(cx, cy, cz + r)]
    for i in range(1, nlat):
        phi = math.pi * i / nlat
        for j in range(nlon):
            theta = 2.0 * math.pi * j / nlon
            verts.append((cx + r * math.sin(phi) * math.cos(theta),
                          cy + r * math.sin(phi) * math.sin(theta), cz + r * math.cos(phi)))
    verts.append((cx, cy, cz - r))
    faces, south = [], len(verts) - 1
    for j in range(nlon):
        j1 = (j + 1) % nlon
        faces.append((0, 1 + j, 1 + j1))
        for i in range(nlat - 2):
            a, b = 1 + i * nlon, 1 + (i + 1) * nlon
            faces.append((a + j, b + j, b + j1, a + j1))
        faces.append((1 + (nlat - 2) * nlon + j, south, 1 + (nlat - 2) * nlon + j1))
    mesh = bpy.data.meshes.new("v%d" % index)
    mesh.from_pydata(verts, [], faces)
    mat = bpy.data.materials.new("volume%d" % index)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    geometry = nodes.new("ShaderNodeNewGeometry")
    distance = nodes.new("ShaderNodeVectorMath")
    distance.operation = "DISTANCE"
    distance.inputs[1].default_value = (cx, cy, cz)
    links.new(geometry.outputs["Position"], distance.inputs[0])
    profile = nodes.new("ShaderNodeMath")  # 1 - d / radius = d * (-1 / radius) + 1
    profile.operation = "MULTIPLY_ADD"
    profile.inputs[1].default_value = -1.0 / radius
    profile.inputs[2].default_value = 1.0
    links.new(distance.outputs["Value"], profile.inputs[0])
    clamp = nodes.new("ShaderNodeMath")
    clamp.operation = "MAXIMUM"
    clamp.inputs[1].default_value = 0.0
    links.new(profile.outputs["Value"], clamp.inputs[0])
    scaled = nodes.new("ShaderNodeMath")
    scaled.operation = "MULTIPLY"
    scaled.inputs[1].default_value = density
    links.new(clamp.outputs["Value"], scaled.inputs[0])
    absorb = nodes.new("ShaderNodeVolumeAbsorption")
    absorb.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    links.new(scaled.outputs["Value"], absorb.inputs["Density"])
    out = nodes.new("ShaderNodeOutputMaterial")
    links.new(absorb.outputs["Volume"], out.inputs["Volume"])
    # Steps of a fiftieth of the default (a tenth of the object's size):
    # about 500 across the blob, so the march's error is far below 1e-3.
    mat.cycles.volume_step_rate = 0.02
    mat.cycles.homogeneous_volume = False
    mesh.materials.append(mat)
    obj = bpy.data.objects.new("volume%d" % index, mesh)
    obj.visible_camera = False
    obj.visible_shadow = bool(casts)
    scene.collection.objects.link(obj)


def add_camera(scene, camera, depth):
    """Camera: columns (r, u, -f, E), vertical sensor fit."""
    eye = Vector(camera[0:3])
    f = (Vector(camera[3:6]) - eye).normalized()
    r = f.cross(Vector(camera[6:9])).normalized()
    u = r.cross(f)
    cam_data = bpy.data.cameras.new("camera")
    cam_data.type = "PERSP"
    cam_data.sensor_fit = "VERTICAL"
    cam_data.angle_y = math.radians(camera[9])
    cam_data.shift_x = 0.0
    cam_data.shift_y = 0.0
    cam_data.clip_start = depth[0]
    cam_data.clip_end = depth[1]
    cam = bpy.data.objects.new("camera", cam_data)
    cam.matrix_world = Matrix(((r.x, u.x, -f.x, eye.x), (r.y, u.y, -f.y, eye.y),
                               (r.z, u.z, -f.z, eye.z), (0.0, 0.0, 0.0, 1.0)))
    scene.collection.objects.link(cam)
    scene.camera = cam


def main():
    datafile, outdir, preset, colour = parse_arguments()
    width, height, samples, camera, clip, lights, objects, volumes = read_data(datafile)
    if colour:
        # (samples, seed, pixel centre): many samples, all at the pixel centre.
        samples = (COLOR_SAMPLES, samples[1], 1)
    scene = empty_scene()
    depth = setup_renderer(scene, preset, colour, samples, camera, clip, objects)
    setup_output(scene, width, height)
    materials = {}
    for index, obj_data in enumerate(objects):
        add_mesh(scene, index, obj_data, preset, colour, materials)
    for index, volume in enumerate(volumes):
        add_volume(scene, index, volume)
    scene.cycles.volume_max_steps = 4096
    add_camera(scene, camera, depth)
    exr = os.path.join(outdir, "render.exr")
    if colour:
        render_colour(scene, lights, objects, depth, exr, outdir, width, height)
    else:
        render_lights(scene, lights, objects, depth, preset, exr, outdir, width, height)


main()
