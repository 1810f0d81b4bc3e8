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

// Every light, each inside `#if (<condition with K>)`.
void PovLights(std::string& o, const ExportScene& s, const std::string& condition)
{
  for (size_t k = 0; k < s.lights.size(); ++k)
  {
    const ExportLight& L = s.lights[k];
    std::string c = condition;
    c.replace(c.find('K'), 1, std::to_string(k));
    o += "#if (" + c + ")\n  light_source { ";
    Vec(o, L.position);
    o += " color rgb 1";
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
    o += " }\n#end\n";
  }
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

const char* const kPovHeader =
  "// Written by vtkshadow-compare: numbers only, nothing from the scene file's text.\n"
  "#version 3.7;\n";
} // namespace

std::string PovScene(const ExportScene& s)
{
  std::string o;
  o.reserve(1 << 20);
  o += kPovHeader;
  o += "global_settings { assumed_gamma 1.0 ambient_light 0 max_trace_level 1 }\n";
  o += "#ifndef (VSH_LIGHT) #declare VSH_LIGHT = 0; #end\n";
  o += "#ifndef (VSH_SHADOWS) #declare VSH_SHADOWS = 1; #end\n";
  PovCamera(o, s);
  PovLights(o, s, "VSH_LIGHT = K");
  o += "#declare VSH_T = texture { pigment { rgb 1 } finish { ambient 0 emission 0 diffuse 1 "
       "brilliance 1 specular 0 phong 0 reflection 0 } }\n";
  for (const ExportObject& ob : s.objects)
    PovMesh(o, ob,
      std::string(" texture { VSH_T }\n") +
        (ob.casts ? " #if (VSH_SHADOWS = 0) no_shadow #end\n" : " no_shadow\n"));
  return o;
}

std::string PovColourScene(const ExportScene& s)
{
  std::string o;
  o.reserve(1 << 20);
  o += kPovHeader;
  // Two levels: the camera ray and one reflection (the pass draws one bounce).
  o += "global_settings { assumed_gamma 1.0 ambient_light 0 max_trace_level 2 }\n";
  o += "#ifndef (VSH_MIRROR_MASK) #declare VSH_MIRROR_MASK = 0; #end\n";
  PovCamera(o, s);
  PovLights(o, s, "K >= 0 & VSH_MIRROR_MASK = 0");
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

std::string CyclesData(const ExportScene& s, int samples)
{
  std::string o;
  o.append("VSHCYC02", 8);
  Put<int32_t>(o, s.width);
  Put<int32_t>(o, s.height);
  Put<int32_t>(o, samples);
  Put<int32_t>(o, 0);
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
  }
  for (const ExportObject& ob : s.objects)
  {
    Put<int32_t>(o, static_cast<int32_t>(ob.points.size() / 3));
    Put<int32_t>(o, static_cast<int32_t>(ob.triangles.size() / 3));
    Put<int32_t>(o, ob.casts ? 1 : 0);
    for (int i = 0; i < 3; ++i)
      Put<double>(o, ob.color[i]);
    Put<double>(o, ob.mirror);
    for (double v : ob.points)
      Put<double>(o, v);
    for (double v : ob.normals)
      Put<double>(o, v);
    for (uint32_t v : ob.triangles)
      Put<int32_t>(o, static_cast<int32_t>(v));
  }
  return o;
}

} // namespace vsh_harness
