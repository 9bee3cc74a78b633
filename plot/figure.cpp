#include "plot/figure.hpp"

#include <cairo-svg.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <utility>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace rheomag::plot {

namespace {

/// Cairo's stream callback: appends the bytes to the std::string in `closure`.
cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

/// Lower-case extension of `path` (".png").
std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return ext;
}

/// Replays `recording` onto `target` and finishes the target's drawing.
void replay(cairo_surface_t* recording, cairo_surface_t* target) {
  cairo_t* cr = cairo_create(target);
  cairo_set_source_surface(cr, recording, 0.0, 0.0);
  cairo_paint(cr);
  cairo_destroy(cr);
  cairo_surface_flush(target);
}

}  // namespace

Figure::Figure(int width, int height) : width_(width), height_(height) {
  const cairo_rectangle_t extents{0.0, 0.0, static_cast<double>(width),
                                  static_cast<double>(height)};
  surface_ = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, &extents);
  cr_ = cairo_create(surface_);
  cairo_set_source_rgb(cr_, 1.0, 1.0, 1.0);
  cairo_paint(cr_);
  cairo_select_font_face(cr_, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
}

Figure::~Figure() {
  if (cr_) cairo_destroy(cr_);
  if (surface_) cairo_surface_destroy(surface_);
}

Figure::Figure(Figure&& other) noexcept
    : width_(other.width_),
      height_(other.height_),
      surface_(std::exchange(other.surface_, nullptr)),
      cr_(std::exchange(other.cr_, nullptr)) {}

Figure& Figure::operator=(Figure&& other) noexcept {
  std::swap(width_, other.width_);
  std::swap(height_, other.height_);
  std::swap(surface_, other.surface_);
  std::swap(cr_, other.cr_);
  return *this;
}

std::string Figure::png() const {
  cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width_, height_);
  replay(surface_, image);
  std::string bytes;
  const cairo_status_t status = cairo_surface_write_to_png_stream(image, append_bytes, &bytes);
  cairo_surface_destroy(image);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("PNG encoding failed: ") + cairo_status_to_string(status));
  return bytes;
}

std::string Figure::svg() const {
  std::string text;
  cairo_surface_t* svg = cairo_svg_surface_create_for_stream(append_bytes, &text, width_, height_);
  replay(surface_, svg);
  cairo_surface_finish(svg);
  const cairo_status_t status = cairo_surface_status(svg);
  cairo_surface_destroy(svg);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("SVG writing failed: ") + cairo_status_to_string(status));
  return text;
}

bool is_picture_path(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".png" || ext == ".svg";
}

void Figure::write(const std::filesystem::path& path, const std::string& what) const {
  if (!is_picture_path(path))
    throw InputError(what + ": expected a file name ending in .png or .svg, got '" + path.string() +
                     "'");
  if (lower_extension(path) == ".svg") {
    write_file_atomically(path, svg());  // text: checked for non-finite numbers on the way
    return;
  }
  // Not write_file_atomically: PNG bytes may spell "nan" by chance, which its text check refuses.
  const std::string bytes = png();
  write_file_atomically_with(path, [&bytes](const std::filesystem::path& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return static_cast<bool>(out.flush());
  });
}

}  // namespace rheomag::plot
