#pragma once
// A small RGB float image for the pictures a study returns, with the few drawing operations the plots need
// (anti-aliased polygons, lines and text from stb_easy_font's built-in bitmap font) and PNG encoding.
// Pixel values are display-referred: sRGB-encoded in [0, 1].
#include <array>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace facetlight {

struct Rgb {
    float r = 0, g = 0, b = 0;
};

class Image {
  public:
    Image(int width, int height, Rgb fill = {});

    int width() const { return width_; }
    int height() const { return height_; }
    Rgb& at(int x, int y) { return pixels_[size_t(y) * width_ + x]; }
    const Rgb& at(int x, int y) const { return pixels_[size_t(y) * width_ + x]; }
    // Mixes c over the pixel with opacity alpha in [0, 1]; ignores pixels outside the image.
    void blend(int x, int y, const Rgb& c, float alpha);

  private:
    int width_, height_;
    std::vector<Rgb> pixels_;
};

// The pixels as 8-bit RGB, row by row (values clamped to [0, 1]).
std::vector<unsigned char> toRgb8(const Image& image);
// An 8-bit RGB PNG of the image (values clamped to [0, 1]).
std::string encodePng(const Image& image);

using Point2 = std::array<double, 2>;  // pixel coordinates, y down; pixel (i, j) covers [i, i+1) x [j, j+1)

// Fills a simple polygon (either orientation) with anti-aliased edges.
void fillPolygon(Image& image, std::span<const Point2> polygon, const Rgb& c, float alpha = 1);
void drawLine(Image& image, Point2 a, Point2 b, double width, const Rgb& c);
void drawPolyline(Image& image, std::span<const Point2> points, bool closed, double width, const Rgb& c);

// Text in stb_easy_font's 7-pixel font magnified by `scale`; (x, y) is the top-left corner. '\n' breaks
// lines.
enum class Align { Left, Center, Right };
void drawText(Image& image, double x, double y, std::string_view text, double scale, const Rgb& c,
              Align align = Align::Left);
double textWidth(std::string_view text, double scale);
double textHeight(double scale);  // of one line
// `text` as one line no wider than `width` at `scale` or, where it is wider, two: broken after its last ", ",
// "; " or ": " that lets the first line fit (a picture's subtitle at a legible size rather than shrunk). The
// second is empty when one line fits or no break helps.
std::pair<std::string, std::string> breakToFit(std::string_view text, double scale, double width);
// `text` in as many lines as it takes, each broken as breakToFit() breaks it or, where no separator lets the
// line fit, with `atSpaces` at its last space that does (a word wider than `width` stays whole), without it
// after its first separator (a part wider than `width` alone on its line).
std::vector<std::string> wrapToFit(std::string_view text, double scale, double width, bool atSpaces = true);

}  // namespace facetlight
