// test_mesh_read_fuzz.cxx - deterministic mutation fuzzing of mesh loading as
// the tools do it: vtkShadowScene::Load on a scene whose one object is the
// mutated mesh, i.e. our byte checker, VTK's reader, the decoded-cells check,
// triangulation and normals. The contract: Load never crashes; it either
// succeeds with triangles whose points are finite, or fails with
// "SCENE: objects[0].mesh: ..." on one line.
//
// Usage: test_mesh_read_fuzz WORKDIR SEED...   (env VSH_FUZZ_ITERATIONS, default 1000)
//        test_mesh_read_fuzz --load WORKDIR MESH...   (prints what each file gets)
// The mutated file is WORKDIR/mesh.EXT: after a crash it is the input to look at.
#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkLogger.h"
#include "vtkObject.h"
#include "vtkOutputWindow.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkShadowScene.h"

extern "C"
{
#include "mesh_mutate.h"
}

#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>

namespace
{
int failures = 0;

std::string Extension(const std::string& path)
{
  const auto dot = path.find_last_of('.');
  return dot == std::string::npos ? "" : path.substr(dot);
}

// A scene with one mesh object, written once per extension.
std::string WriteScene(const std::string& dir, const std::string& meshPath)
{
  const std::string scene = dir + "/scene" + Extension(meshPath) + ".json";
  FILE* f = std::fopen(scene.c_str(), "w");
  if (!f)
  {
    std::perror(scene.c_str());
    std::exit(1);
  }
  std::fprintf(f,
    "{\"size\": [64, 48], \"camera\": {\"position\": [2, -3, 2], \"focal_point\": [0, 0, 0], "
    "\"view_up\": [0, 0, 1], \"view_angle\": 45}, \"lights\": [{\"type\": \"directional\", "
    "\"direction\": [0, 0, -1]}], \"objects\": [{\"mesh\": \"%s\"}]}\n",
    meshPath.c_str());
  std::fclose(f);
  return scene;
}

bool WriteBytes(const std::string& path, const char* data, size_t size)
{
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f)
  {
    return false;
  }
  const bool ok = std::fwrite(data, 1, size, f) == size;
  return std::fclose(f) == 0 && ok;
}

// Loads the scene; checks the contract. Returns 1 loaded, 0 refused, -1 broken.
int LoadAndCheck(const std::string& scene, std::string* message)
{
  vtkNew<vtkShadowScene> s;
  if (!s->Load(scene.c_str()))
  {
    const std::string err = s->GetErrorMessage();
    if (message)
    {
      *message = err;
    }
    const std::string prefix = scene + ": objects[0].mesh: ";
    return err.compare(0, prefix.size(), prefix) == 0 && err.find('\n') == std::string::npos
      ? 0
      : -1;
  }
  vtkPolyData* poly = s->GetObjectPolyData(0);
  if (!poly || poly->GetNumberOfPolys() == 0)
  {
    return -1;
  }
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
  {
    double p[3];
    poly->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return -1;
    }
  }
  if (message)
  {
    *message = "loaded, " + std::to_string(poly->GetNumberOfPolys()) + " triangles";
  }
  return 1;
}

int LoadMode(int argc, char** argv)
{
  for (int i = 3; i < argc; ++i)
  {
    std::string message;
    const std::string scene = WriteScene(argv[2], argv[i]);
    const int rc = LoadAndCheck(scene, &message);
    std::printf("%s: %s%s\n", argv[i], rc < 0 ? "CONTRACT BROKEN: " : "", message.c_str());
  }
  return 0;
}

void FuzzSeed(const std::string& dir, const char* seedPath, int index, long iterations)
{
  size_t seedLen = 0;
  char* seed = mm_read_file(seedPath, &seedLen);
  if (!seed)
  {
    std::fprintf(stderr, "cannot read %s\n", seedPath);
    ++failures;
    return;
  }
  const std::string mesh = dir + "/mesh" + Extension(seedPath);
  const std::string scene = WriteScene(dir, mesh);
  long loaded = 0, refused = 0;
  std::printf("%s: ", seedPath);
  if (!WriteBytes(mesh, seed, seedLen) || LoadAndCheck(scene, nullptr) != 1)
  {
    std::fprintf(stderr, "%s: the seed itself does not load\n", seedPath);
    ++failures;
  }
  mm_buf b = { nullptr, 0, 0 };
  for (long it = 0; it < iterations; ++it)
  {
    mm_make(&b, seed, seedLen, index, it);
    std::string message;
    if (!WriteBytes(mesh, b.data, b.len))
    {
      std::fprintf(stderr, "cannot write %s\n", mesh.c_str());
      std::exit(1);
    }
    const int rc = LoadAndCheck(scene, &message);
    if (rc < 0)
    {
      ++failures;
      std::fprintf(stderr, "  %s iteration %ld: contract broken: \"%s\"\n", seedPath, it,
        message.c_str());
    }
    (rc == 1 ? loaded : refused) += 1;
    if (it % 1000 == 999 && it + 1 < iterations)
    {
      std::printf("%ld ", it + 1);
    }
  }
  std::printf("%ld mutations, %ld loaded, %ld refused\n", iterations, loaded,
    refused);
  if (loaded == 0 || refused == 0)
  {
    std::fprintf(stderr, "  %s: the mutations explored only one side\n", seedPath);
    ++failures;
  }
  std::free(b.data);
  std::free(seed);
}
} // namespace

int main(int argc, char** argv)
{
  // Quiet, but not GlobalWarningDisplayOff(): VTK 9.1 raises ErrorEvent (how
  // the loader learns of reader errors) only while warnings are displayed.
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  std::setvbuf(stdout, nullptr, _IONBF, 0);  // what ran before a crash is on the log
  if (argc > 3 && std::strcmp(argv[1], "--load") == 0)
  {
    return LoadMode(argc, argv);
  }
  if (argc < 3)
  {
    std::fprintf(stderr, "usage: test_mesh_read_fuzz WORKDIR SEED...\n");
    return 1;
  }
  long iterations = 1000;
  if (const char* env = std::getenv("VSH_FUZZ_ITERATIONS"))
  {
    iterations = std::atol(env);
  }
  const std::clock_t start = std::clock();
  for (int i = 2; i < argc; ++i)
  {
    FuzzSeed(argv[1], argv[i], i, iterations);
  }
  std::printf("%.1f s CPU\nmesh.read_fuzz: %d failures\n",
    double(std::clock() - start) / CLOCKS_PER_SEC, failures);
  return failures ? 1 : 0;
}
