#include "vtkShadowPNG.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <unistd.h>

namespace vtkshadow
{
namespace
{
std::string TemporaryName(const std::string& path)
{
  return path + ".tmp" + std::to_string(static_cast<long>(getpid()));
}

bool Publish(const std::string& temporary, const std::string& path, std::string& error)
{
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    error = path + ": cannot write (" + std::strerror(errno) + ")";
    std::remove(temporary.c_str());
    return false;
  }
  return true;
}
}

bool WritePNGAtomically(vtkImageData* image, const std::string& path, std::string& error)
{
  const std::string temporary = TemporaryName(path);
  {
    std::ofstream probe(temporary, std::ios::binary);
    if (!probe)
    {
      error = path + ": cannot write (" + std::strerror(errno) + ")";
      return false;
    }
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(temporary.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    error =
      path + ": PNG writer failed (error code " + std::to_string(writer->GetErrorCode()) + ")";
    std::remove(temporary.c_str());
    return false;
  }
  return Publish(temporary, path, error);
}

bool WriteTextAtomically(const std::string& text, const std::string& path, std::string& error)
{
  const std::string temporary = TemporaryName(path);
  {
    std::ofstream out(temporary, std::ios::binary);
    if (!out || !(out << text) || !out.flush())
    {
      error = path + ": cannot write (" + std::strerror(errno) + ")";
      std::remove(temporary.c_str());
      return false;
    }
  }
  return Publish(temporary, path, error);
}
}
