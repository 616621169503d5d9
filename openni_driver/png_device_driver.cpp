// The OpenNI2 driver of the virtual sensor (libRdsfPngDevice.so): opens "rdsf-png://<folder>" addresses as
// devices serving the folder's PNGs (png_device.hpp). It announces no device by itself, so "any device"
// still means a real sensor.
#include <list>
#include <string>

// ONI_EXPORT_DRIVER allocates with the XnLib macros, which OpenNI2's public headers do not ship.
#define XN_NEW(type, ...) new type(__VA_ARGS__)
#define XN_DELETE(p) delete (p)
#include <Driver/OniDriverAPI.h>

#include "png_device.hpp"
#include "png_device_uri.hpp"
#include "png_sequence.hpp"

namespace rdsf::openni_driver {
namespace {

void copy_text(char (&target)[ONI_MAX_STR], const std::string& text) {
  const std::size_t n = std::min(text.size(), static_cast<std::size_t>(ONI_MAX_STR - 1));
  text.copy(target, n);
  target[n] = '\0';
}

// Parses the address and lists its folder; false with a one-line `error` when either fails.
bool open_sequence(const std::string& uri, PngDeviceUri& parsed, PngSequence& sequence, std::string& error) {
  if (!parse_png_device_uri(uri, parsed, error) || !sequence.open(parsed.folder, error)) return false;
  if (!parsed.depth && !sequence.has_colour()) {
    error = parsed.folder + ": depth=off needs NAME.rgb.png for every frame (the device would offer no stream)";
    return false;
  }
  return true;
}

}  // namespace

class PngDeviceDriver : public oni::driver::DriverBase {
 public:
  explicit PngDeviceDriver(OniDriverServices* services) : DriverBase(services) {}

  OniStatus tryDevice(const char* uri) override {
    if (uri == nullptr || !is_png_device_uri(uri)) return ONI_STATUS_ERROR;
    PngDeviceUri parsed;
    PngSequence sequence;
    std::string error;
    if (!open_sequence(uri, parsed, sequence, error)) {
      getServices().errorLoggerAppend("%s", error.c_str());
      return ONI_STATUS_ERROR;
    }
    OniDeviceInfo& info = announced_.emplace_back();
    copy_text(info.uri, uri);
    copy_text(info.vendor, "rdsf workbench");
    copy_text(info.name, "PNG folder (virtual sensor)");
    info.usbVendorId = 0;
    info.usbProductId = 0;
    deviceConnected(&info);
    return ONI_STATUS_OK;
  }

  oni::driver::DeviceBase* deviceOpen(const char* uri, const char* /*mode*/) override {
    PngDeviceUri parsed;
    PngSequence sequence;
    std::string error;
    if (uri == nullptr || !open_sequence(uri, parsed, sequence, error)) {
      getServices().errorLoggerAppend("%s", error.c_str());
      return nullptr;
    }
    return new PngDevice(std::move(sequence), parsed, getServices());
  }

  void deviceClose(oni::driver::DeviceBase* device) override { delete device; }

  void shutdown() override {}

 private:
  std::list<OniDeviceInfo> announced_;  // OpenNI2 copies them; kept for the driver's lifetime anyway
};

}  // namespace rdsf::openni_driver

ONI_EXPORT_DRIVER(rdsf::openni_driver::PngDeviceDriver)
