// readImage and writeImage through the image module (image_module.h), loaded from the directory
// of the running executable on the first call, for the programs that compile this file instead
// of linking image.cxx (the mesh reader program). A module that is missing or does not match
// fails that call with the file's name and the reason; everything that needs no image works.
#include "core/error.h"
#include "core/image/image_module.h"

#include <dlfcn.h>
#include <filesystem>
#include <mutex>
#include <system_error>

namespace aniso
{
namespace
{
const ImageModule* loadModule(std::string& failure)
{
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec)
  {
    failure = "the image module cannot be found (/proc/self/exe: " + ec.message() + ")";
    return nullptr;
  }
  const std::string file = (self.parent_path() / kImageModuleFile).string();
  // Kept for the process's life; RTLD_LOCAL: nothing of the module but its entry is looked up.
  void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle)
  {
    const char* reason = ::dlerror();
    failure = "the image module does not load (" + std::string(reason ? reason : file) + ")";
    return nullptr;
  }
  using Entry = const ImageModule* (*)();
  auto entry = reinterpret_cast<Entry>(::dlsym(handle, kImageModuleEntry));
  const ImageModule* module = entry ? entry() : nullptr;
  if (!module || module->version != kImageModuleVersion || !module->read || !module->write)
  {
    failure = file + " is not the image module of this program's version";
    return nullptr;
  }
  return module;
}

std::once_flag loadOnce;
const ImageModule* loadedModule = nullptr;
std::string loadFailure;

const ImageModule& imageModule(const std::string& path)
{
  loadImageModule();
  if (!loadedModule)
  {
    throw errorAbout(path, loadFailure);
  }
  return *loadedModule;
}
} // namespace

void loadImageModule()
{
  std::call_once(loadOnce, [] { loadedModule = loadModule(loadFailure); });
}

Image readImage(const std::string& path, ImageInfo* info)
{
  return imageModule(path).read(path, info);
}

void writeImage(const std::string& path, const Image& image, const WriteOptions& options)
{
  imageModule(path).write(path, image, options);
}
} // namespace aniso
