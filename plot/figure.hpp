#pragma once
// One picture: drawn once with Cairo into a recording surface, then written as PNG or SVG.

#include <cairo.h>

#include <filesystem>
#include <string>

namespace rheomag::plot {

/// A width x height picture (pixels in PNG, points in SVG) on a white background; draw on
/// `cr()`, then write it in either format.
class Figure {
 public:
  /// A blank (white) width x height picture.
  Figure(int width, int height);
  /// Releases the Cairo context and surface.
  ~Figure();
  /// Takes over `other`'s drawing (other is left empty).
  Figure(Figure&& other) noexcept;
  /// Swaps drawings with `other`.
  Figure& operator=(Figure&& other) noexcept;
  Figure(const Figure&) = delete;
  Figure& operator=(const Figure&) = delete;

  /// The Cairo context to draw with (user units = pixels, origin top left).
  cairo_t* cr() const { return cr_; }
  /// Width in pixels.
  int width() const { return width_; }
  /// Height in pixels.
  int height() const { return height_; }
  /// The picture as PNG bytes.
  std::string png() const;
  /// The picture as SVG text.
  std::string svg() const;
  /// Writes the picture atomically as PNG or SVG, by the extension of `path` (".png" / ".svg";
  /// InputError naming `what` for any other).
  void write(const std::filesystem::path& path, const std::string& what) const;

 private:
  int width_ = 0, height_ = 0;
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

/// True when `path` ends in ".png" or ".svg" (any case).
bool is_picture_path(const std::filesystem::path& path);

}  // namespace rheomag::plot
