#include "rdsf/frame/image_codecs.hpp"

#ifdef RDSF_IMAGE_CODECS_MODULE
#include <dlfcn.h>

#include <cstring>
#include <filesystem>

#include "rdsf/core/error.hpp"
#include "rdsf/version.hpp"
#endif

namespace rdsf {
namespace {

#ifdef RDSF_IMAGE_CODECS_MODULE
// Beside the file of the shared library holding this code (dladdr): the build tree's src/ and the installed
// LIBDIR alike.
std::string module_path() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&image_codecs_module_path), &info) == 0 || info.dli_fname == nullptr) {
    return RDSF_IMAGE_CODECS_MODULE;
  }
  return (std::filesystem::path(info.dli_fname).parent_path() / RDSF_IMAGE_CODECS_MODULE).string();
}

const ImageCodecsTable& load_table() {
  const std::string path = module_path();
  // Kept open for the process's life: the table points into it.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* error = dlerror();
    std::string why = error != nullptr ? error : "dlopen failed";
    if (why.rfind(path + ": ", 0) == 0) why.erase(0, path.size() + 2);  // dlerror names the file too
    fail(path, "cannot load OpenCV's image codecs (" + why + ")");
  }
  auto entry = reinterpret_cast<const ImageCodecsTable* (*)()>(dlsym(handle, "rdsf_image_codecs"));
  const ImageCodecsTable* table = entry != nullptr ? entry() : nullptr;
  if (table == nullptr) fail(path, "not librdsf's image codecs module (no rdsf_image_codecs)");
  if (std::strcmp(table->version, RDSF_VERSION_STRING) != 0) {
    fail(path, std::string("image codecs module of librdsf ") + table->version + ", not of this librdsf " +
                   RDSF_VERSION_STRING);
  }
  return *table;
}
#else
const ImageCodecsTable& load_table() { return *rdsf_image_codecs(); }
#endif

// Opened at the first call, once per process (a function-local static's initialisation is thread-safe; a
// failed one is tried again at the next call).
const ImageCodecsTable& table() {
  static const ImageCodecsTable& loaded = load_table();
  return loaded;
}

}  // namespace

cv::Mat opencv_decode_image(const unsigned char* data, std::size_t size, DecodedAs as) {
  return table().decode(data, size, as);
}

bool opencv_encode_png(const cv::Mat& image, std::vector<unsigned char>& bytes, int compression_level) {
  return table().encode_png(image, bytes, compression_level);
}

void open_image_codecs() { (void)table(); }

std::string image_codecs_module_path() {
#ifdef RDSF_IMAGE_CODECS_MODULE
  return module_path();
#else
  return "";
#endif
}

}  // namespace rdsf
