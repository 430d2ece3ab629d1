// SPDX-License-Identifier: MIT
#include "engine/render/image_codecs.h"

#include <dlfcn.h>
#include <unistd.h>

#include <new>
#include <string>
#include <system_error>
#include <vector>

#include "core/errors.h"

namespace rpt::engine {

std::vector<std::filesystem::path> ImageCodecsPlaces() {
  std::vector<std::filesystem::path> places;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) places.push_back(exe.parent_path() / kImageCodecsFile);
#ifdef RPT_IMAGE_CODECS_BUILD_PATH
  const std::filesystem::path built = RPT_IMAGE_CODECS_BUILD_PATH;
  if (places.empty() || places.front() != built) places.push_back(built);
#endif
  return places;
}

namespace {

// Out of memory inside dlopen: a constructor of one of the module's libraries (GDCM's, say) that
// allocates and fails throws std::bad_alloc out of the loader, which ends in std::terminate. While
// the module loads, a failed allocation ends the process with a message instead.
void OutOfMemoryLoadingTheModule() {
  static constexpr char kMessage[] =
      "error: out of memory loading rpt render's image and video module (librpt_image_codecs.so and the OpenCV "
      "image and video libraries it loads)\n";
  [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
  _exit(1);
}

bool LooksLikeOutOfMemory(const std::string& why) {
  return why.find("failed to map segment") != std::string::npos ||
         why.find("Cannot allocate memory") != std::string::npos;
}

}  // namespace

const ImageCodecs& LoadImageCodecsFrom(std::span<const std::filesystem::path> places) {
  std::string tried;
  bool out_of_memory = false;
  for (const std::filesystem::path& place : places) {
    std::string why;
    const std::new_handler previous = std::set_new_handler(OutOfMemoryLoadingTheModule);
    // RTLD_LOCAL: the module's OpenCV symbols stay out of the process's global lookup.
    void* handle = dlopen(place.c_str(), RTLD_NOW | RTLD_LOCAL);
    std::set_new_handler(previous);
    if (handle != nullptr) {
      using Entry = const ImageCodecs* (*)();
      const auto entry = reinterpret_cast<Entry>(dlsym(handle, kImageCodecsEntry));
      const ImageCodecs* codecs = entry != nullptr ? entry() : nullptr;
      if (codecs != nullptr && codecs->version == kImageCodecsVersion) return *codecs;  // stays loaded
      why = entry == nullptr ? std::string("no function ") + kImageCodecsEntry
                             : "built by another version of rpt (rebuild it with rpt)";
      dlclose(handle);
    } else {
      const char* error = dlerror();
      why = error != nullptr ? error : "cannot be loaded";
      out_of_memory = out_of_memory || LooksLikeOutOfMemory(why);
    }
    tried += "\n  " + place.string() + ": " + why;
  }
  if (places.empty()) tried = " (no place to look)";
  if (out_of_memory) {
    throw InstallationError(std::string("out of memory loading rpt render's image and video module ") +
                            kImageCodecsFile + " (the OpenCV image and video libraries need about 250 MB of "
                            "address space); tried:" + tried);
  }
  throw InstallationError(std::string("rpt render needs its image and video module ") + kImageCodecsFile +
                          ", built with rpt (cmake --build <build dir> --target rpt); tried:" + tried);
}

const ImageCodecs& LoadImageCodecs() {
  static const ImageCodecs& codecs = LoadImageCodecsFrom(ImageCodecsPlaces());  // a failure is retried
  return codecs;
}

}  // namespace rpt::engine
