#include "harness_export.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>

namespace vsh_harness
{
namespace
{
void Num(std::string& o, double v)
{
  char buf[40];
  snprintf(buf, sizeof buf, "%.17g", v);
  o += buf;
}

void Vec(std::string& o, const double* v)
{
  o += '<';
  Num(o, v[0]);
  o += ',';
  Num(o, v[1]);
  o += ',';
  Num(o, v[2]);
  o += '>';
}

template <typename T>
void Put(std::string& o, T v)
{
  // Little-endian on every platform Debian's Blender runs on; the script
  // byteswaps on big-endian hosts, and this writer does the same.
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
  for (size_t i = 0; i < sizeof(T) / 2; ++i)
    std::swap(b[i], b[sizeof(T) - 1 - i]);
#endif
  o.append(reinterpret_cast<const char*>(b), sizeof(T));
}

void PovCamera(std::string& o, const ExportScene& s)
{
  const double a = static_cast<double>(s.width) / s.height;
  const double t = std::tan(s.view_angle * M_PI / 360.0);
  const double horizontal = 2.0 * std::atan(a * t) * 180.0 / M_PI;
  o += "camera { perspective location ";
  Vec(o, s.eye);
  o += " sky ";
  Vec(o, s.up);
  o += " up y right -x*";
  Num(o, a);
  o += " angle ";
  Num(o, horizontal);
  o += " look_at ";
  Vec(o, s.focal);
  o += " }\n";
  o += "background { rgb 0 }\n";
}

// Two unit vectors perpendicular to `axis` and to each other, turned about
// it by `turn` radians.
void Perpendiculars(const double axis[3], double turn, double a[3], double b[3])
{
  const double h[3] = { std::fabs(axis[0]) < 0.9 ? 1.0 : 0.0, std::fabs(axis[0]) < 0.9 ? 0.0 : 1.0,
    0.0 };
  double u[3] = { h[1] * axis[2] - h[2] * axis[1], h[2] * axis[0] - h[0] * axis[2],
    h[0] * axis[1] - h[1] * axis[0] };
  const double n = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (double& x : u)
    x /= n;
  const double v[3] = { axis[1] * u[2] - axis[2] * u[1], axis[2] * u[0] - axis[0] * u[2],
    axis[0] * u[1] - axis[1] * u[0] };
  for (int i = 0; i < 3; ++i)
  {
    a[i] = std::cos(turn) * u[i] + std::sin(turn) * v[i];
    b[i] = -std::sin(turn) * u[i] + std::cos(turn) * v[i];
  }
}

// POV-Ray's area light for a light with a size (docs/harness.md, "Lights
// with a size"). Point and spot: a disk of diameter 2r, `orient` turns it to
// face each shaded point (Cycles' disk). Directional: the light sits 1 unit
// before its point_at target, so a disk of diameter 2 tan(angle/2) spans the
// angle seen from the target; its axes are set perpendicular to the
// direction (no orient: every shaded point sees the same parallel disk).
// n = 2^k + 1 gives the edge rows half weight, so the width is the axis
// length; no `adaptive` (it skips small occluders with few samples).
void PovAreaLight(std::string& o, const ExportLight& L, int grid, int seed)
{
  const double d = L.type == 0 ? 2.0 * std::tan(L.size * M_PI / 360.0) : 2.0 * L.size;
  double a[3], b[3];
  // The golden angle per seed: seeds give well-spread turns of the grid.
  Perpendiculars(L.axis, seed * 2.399963229728653, a, b);
  for (int i = 0; i < 3; ++i)
  {
    a[i] *= d;
    b[i] *= d;
  }
  o += " area_light ";
  Vec(o, a);
  o += ", ";
  Vec(o, b);
  // No area_illumination: tried, it moved POV-Ray further from Cycles on a
  // curved caster's terminator (docs/harness.md, "Lights with a size").
  o += ", " + std::to_string(grid) + ", " + std::to_string(grid) + " circular jitter";
  if (L.type != 0)
    o += " orient";
}

// Every light, each inside `#if (<condition with K>)`; lights with a size
// become area lights (PovAreaLight).
void PovLights(
  std::string& o, const ExportScene& s, const std::string& condition, int grid, int seed)
{
  for (size_t k = 0; k < s.lights.size(); ++k)
  {
    const ExportLight& L = s.lights[k];
    std::string c = condition;
    c.replace(c.find('K'), 1, std::to_string(k));
    o += "#if (" + c + ")\n  light_source { ";
    Vec(o, L.position);
    o += " color rgb 1";
    if (L.size > 0)
      PovAreaLight(o, L, grid, seed);
    double target[3];
    for (int i = 0; i < 3; ++i)
      target[i] = L.position[i] + L.axis[i];
    if (L.type == 0)
    {
      o += " parallel point_at ";
      Vec(o, target);
    }
    else if (L.type == 2)
    {
      o += " spotlight radius ";
      Num(o, L.cone);
      o += " falloff ";
      Num(o, L.cone);
      o += " tightness 0 point_at ";
      Vec(o, target);
    }
    // Shadow rays lose what a volume's media absorbs only with
    // media_attenuation (off by default); scenes without volumes keep
    // their text, and so their reference keys.
    if (!s.volumes.empty())
      o += " media_attenuation on";
    o += " }\n#end\n";
  }
}

// A volume (ExportVolume): a hollow, fully transmitting sphere the camera
// does not see, holding absorbing media whose density falls linearly from 1
// at the centre to 0 at the radius (POV-Ray's `spherical` pattern), scaled
// by the extinction at the centre. Enough samples that the media's
// integral along a shadow ray is exact to well under a percent.
void PovVolume(std::string& o, const ExportVolume& v)
{
  o += "sphere { ";
  Vec(o, v.center);
  o += ", ";
  Num(o, v.radius);
  o += "\n hollow texture { pigment { rgbt 1 } finish { ambient 0 emission 0 diffuse 0 } }\n"
       " interior { media { absorption ";
  Num(o, v.density);
  o += " method 3 intervals 1 samples 256\n  density { spherical density_map { [0 rgb 0] "
       "[1 rgb 1] } scale ";
  Num(o, v.radius);
  o += " translate ";
  Vec(o, v.center);
  o += " } } }\n no_image";
  o += v.casts ? " #if (VSH_SHADOWS = 0) no_shadow #end\n}\n" : " no_shadow\n}\n";
}

// One mesh2 with its normals; `tail` follows the face indices (texture,
// shadow flags).
void PovMesh(std::string& o, const ExportObject& ob, const std::string& tail)
{
  const size_t np = ob.points.size() / 3, nt = ob.triangles.size() / 3;
  o += "mesh2 {\n vertex_vectors { " + std::to_string(np);
  for (size_t i = 0; i < np; ++i)
  {
    o += i % 4 ? "," : ",\n  ";
    Vec(o, &ob.points[3 * i]);
  }
  o += " }\n normal_vectors { " + std::to_string(np);
  for (size_t i = 0; i < np; ++i)
  {
    o += i % 4 ? "," : ",\n  ";
    Vec(o, &ob.normals[3 * i]);
  }
  o += " }\n face_indices { " + std::to_string(nt);
  char buf[64];
  for (size_t i = 0; i < nt; ++i)
  {
    snprintf(buf, sizeof buf, "%s<%u,%u,%u>", i % 6 ? "," : ",\n  ", ob.triangles[3 * i],
      ob.triangles[3 * i + 1], ob.triangles[3 * i + 2]);
    o += buf;
  }
  o += " }\n" + tail + "}\n";
}

// A translucent object in the visibility renders: rgbft, so each crossing
// of a shadow ray lets (1 - a) ((1 - f) + f c) through (POV-Ray's filter f
// (1 - a), transmit (1 - f) (1 - a): docs/translucency.md), and no_image:
// the camera sees the opaque surface behind it, whose visibility is the
// measure (vtkShadowScene draws the object black for the same reason).
std::string PovTranslucentTexture(const ExportObject& ob)
{
  const double clear = 1.0 - ob.opacity;
  const double rgbft[5] = { ob.color[0], ob.color[1], ob.color[2], ob.filter * clear,
    (1.0 - ob.filter) * clear };
  std::string t = " texture { pigment { rgbft <";
  for (int i = 0; i < 5; ++i)
  {
    if (i)
      t += ",";
    Num(t, rgbft[i]);
  }
  return t +
    "> } finish { ambient 0 emission 0 diffuse 1 specular 0 phong 0 reflection 0 } }\n"
    " no_image\n";
}

const char* const kPovHeader =
  "// Written by vtkshadow-compare: numbers only, nothing from the scene file's text.\n"
  "#version 3.7;\n";
} // namespace

bool HasSoftLight(const ExportScene& s)
{
  for (const ExportLight& L : s.lights)
    if (L.size > 0)
      return true;
  return false;
}

std::string PovScene(const ExportScene& s, int grid, int seed)
{
  std::string o;
  o.reserve(1 << 20);
  o += kPovHeader;
  o += "global_settings { assumed_gamma 1.0 ambient_light 0 max_trace_level 1 }\n";
  o += "#ifndef (VSH_LIGHT) #declare VSH_LIGHT = 0; #end\n";
  o += "#ifndef (VSH_SHADOWS) #declare VSH_SHADOWS = 1; #end\n";
  PovCamera(o, s);
  PovLights(o, s, "VSH_LIGHT = K", grid, seed);
  o += "#declare VSH_T = texture { pigment { rgb 1 } finish { ambient 0 emission 0 diffuse 1 "
       "brilliance 1 specular 0 phong 0 reflection 0 } }\n";
  for (const ExportObject& ob : s.objects)
    PovMesh(o, ob,
      (ob.opacity < 1 ? PovTranslucentTexture(ob) : std::string(" texture { VSH_T }\n")) +
        (ob.casts ? " #if (VSH_SHADOWS = 0) no_shadow #end\n" : " no_shadow\n"));
  for (const ExportVolume& v : s.volumes)
    PovVolume(o, v);
  return o;
}

std::string PovColourScene(const ExportScene& s, int grid, int seed)
{
  std::string o;
  o.reserve(1 << 20);
  o += kPovHeader;
  // Two levels: the camera ray and one reflection (the pass draws one bounce).
  o += "global_settings { assumed_gamma 1.0 ambient_light 0 max_trace_level 2 }\n";
  o += "#ifndef (VSH_MIRROR_MASK) #declare VSH_MIRROR_MASK = 0; #end\n";
  PovCamera(o, s);
  PovLights(o, s, "K >= 0 & VSH_MIRROR_MASK = 0", grid, seed);
  for (const ExportObject& ob : s.objects)
  {
    const double R = ob.mirror > 0 ? ob.mirror : 0.0;
    std::string t = " #if (VSH_MIRROR_MASK = 0)\n  texture { pigment { rgb ";
    Vec(t, ob.color);
    t += " } finish { ambient 0 emission 0 diffuse ";
    Num(t, 1.0 - R);
    t += " brilliance 1 specular 0 phong 0 reflection { ";
    Num(t, R);
    t += " } } }\n #else\n  texture { pigment { rgb ";
    t += R > 0 ? "1" : "0";
    t += " } finish { ambient 0 emission ";
    t += R > 0 ? "1" : "0";
    t += " diffuse 0 specular 0 phong 0 reflection 0 } }\n #end\n";
    PovMesh(o, ob, t + (ob.casts ? "" : " no_shadow\n"));
  }
  return o;
}

std::string CyclesData(const ExportScene& s, int samples, int soft_samples, int seed)
{
  std::string o;
  // Pixel centre (Gaussian filter 0.01) unless more samples were asked for over
  // the pixel area; soft lights then get their own sample count there.
  const int centre = samples == 1 ? 1 : 0;
  if (centre && HasSoftLight(s))
    samples = soft_samples;
  // Version 04: 03 (soft lights' seed, pixel centre and size; a colour and
  // reflectance per object) with each object's opacity and filter.
  o.append("VSHCYC04", 8);
  Put<int32_t>(o, s.width);
  Put<int32_t>(o, s.height);
  Put<int32_t>(o, samples);
  Put<int32_t>(o, seed);
  Put<int32_t>(o, centre);
  Put<int32_t>(o, static_cast<int32_t>(s.lights.size()));
  Put<int32_t>(o, static_cast<int32_t>(s.objects.size()));
  for (int i = 0; i < 3; ++i)
    Put<double>(o, s.eye[i]);
  for (int i = 0; i < 3; ++i)
    Put<double>(o, s.focal[i]);
  for (int i = 0; i < 3; ++i)
    Put<double>(o, s.up[i]);
  Put<double>(o, s.view_angle);
  double dist = 0;
  for (int i = 0; i < 3; ++i)
    dist += (s.focal[i] - s.eye[i]) * (s.focal[i] - s.eye[i]);
  dist = std::sqrt(dist);
  double far = 0;
  for (int i = 0; i < 3; ++i)
    far += (s.bounds_center[i] - s.eye[i]) * (s.bounds_center[i] - s.eye[i]);
  far = 2.0 * (std::sqrt(far) + s.bounds_diagonal) + 1.0;
  Put<double>(o, 1e-5 * dist);
  Put<double>(o, far);
  for (const ExportLight& L : s.lights)
  {
    Put<double>(o, L.type);
    for (int i = 0; i < 3; ++i)
      Put<double>(o, L.position[i]);
    for (int i = 0; i < 3; ++i)
      Put<double>(o, L.axis[i]);
    Put<double>(o, L.cone);
    Put<double>(o, L.size);
  }
  for (const ExportObject& ob : s.objects)
  {
    Put<int32_t>(o, static_cast<int32_t>(ob.points.size() / 3));
    Put<int32_t>(o, static_cast<int32_t>(ob.triangles.size() / 3));
    Put<int32_t>(o, ob.casts ? 1 : 0);
    for (int i = 0; i < 3; ++i)
      Put<double>(o, ob.color[i]);
    Put<double>(o, ob.mirror);
    Put<double>(o, ob.opacity);
    Put<double>(o, ob.filter);
    for (double v : ob.points)
      Put<double>(o, v);
    for (double v : ob.normals)
      Put<double>(o, v);
    for (uint32_t v : ob.triangles)
      Put<int32_t>(o, static_cast<int32_t>(v));
  }
  // Volumes: an optional trailer (scenes without one keep their bytes, and
  // so their reference keys).
  if (!s.volumes.empty())
  {
    o.append("VOLS", 4);
    Put<int32_t>(o, static_cast<int32_t>(s.volumes.size()));
    for (const ExportVolume& v : s.volumes)
    {
      for (int i = 0; i < 3; ++i)
        Put<double>(o, v.center[i]);
      Put<double>(o, v.radius);
      Put<double>(o, v.density);
      Put<int32_t>(o, v.casts ? 1 : 0);
    }
  }
  return o;
}

} // namespace vsh_harness
