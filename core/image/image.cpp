#include "image/image.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <stb/stb_easy_font.h>
#include <stb/stb_image_write.h>

#include "util/error.h"

namespace facetlight {

Image::Image(int width, int height, Rgb fill) : width_(width), height_(height) {
    if (width < 1 || height < 1) throw Error("an image needs a positive size");
    pixels_.assign(size_t(width) * size_t(height), fill);
}

void Image::blend(int x, int y, const Rgb& c, float alpha) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_ || alpha <= 0) return;
    alpha = std::min(alpha, 1.0f);
    Rgb& p = at(x, y);
    p.r += (c.r - p.r) * alpha;
    p.g += (c.g - p.g) * alpha;
    p.b += (c.b - p.b) * alpha;
}

std::vector<unsigned char> toRgb8(const Image& image) {
    std::vector<unsigned char> bytes(size_t(image.width()) * size_t(image.height()) * 3);
    size_t i = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const Rgb& p = image.at(x, y);
            for (float v : {p.r, p.g, p.b})
                bytes[i++] = (unsigned char)std::lround(std::clamp(v, 0.0f, 1.0f) * 255);
        }
    }
    return bytes;
}

std::string encodePng(const Image& image) {
    const std::vector<unsigned char> bytes = toRgb8(image);
    std::string png;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
    };
    if (!stbi_write_png_to_func(append, &png, image.width(), image.height(), 3, bytes.data(),
                                image.width() * 3)) {
        throw Error("PNG encoding failed");
    }
    return png;
}

void fillPolygon(Image& image, std::span<const Point2> poly, const Rgb& c, float alpha) {
    if (poly.size() < 3) return;
    double yLo = INFINITY, yHi = -INFINITY;
    for (const Point2& p : poly) {
        yLo = std::min(yLo, p[1]);
        yHi = std::max(yHi, p[1]);
    }
    const int row0 = std::max(0, int(std::floor(yLo))),
              row1 = std::min(image.height() - 1, int(std::ceil(yHi)));
    // Coverage by 4 sub-scanlines per row, each span's ends weighted by the fraction of the pixel they cover.
    constexpr int kSub = 4;
    std::vector<double> crossings, coverage(size_t(image.width()) + 1);
    for (int row = row0; row <= row1; ++row) {
        std::fill(coverage.begin(), coverage.end(), 0.0);
        int lo = image.width(), hi = -1;
        for (int s = 0; s < kSub; ++s) {
            const double y = row + (s + 0.5) / kSub;
            crossings.clear();
            for (size_t i = 0; i < poly.size(); ++i) {
                const Point2& a = poly[i];
                const Point2& b = poly[(i + 1) % poly.size()];
                if ((a[1] <= y) != (b[1] <= y))
                    crossings.push_back(a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]));
            }
            std::sort(crossings.begin(), crossings.end());
            for (size_t k = 0; k + 1 < crossings.size(); k += 2) {
                const double x0 = std::clamp(crossings[k], 0.0, double(image.width()));
                const double x1 = std::clamp(crossings[k + 1], 0.0, double(image.width()));
                for (int x = int(x0); x < image.width() && x < x1; ++x) {
                    coverage[x] += (std::min(x1, x + 1.0) - std::max(x0, double(x))) / kSub;
                    lo = std::min(lo, x);
                    hi = std::max(hi, x);
                }
            }
        }
        for (int x = lo; x <= hi; ++x) image.blend(x, row, c, float(coverage[x]) * alpha);
    }
}

void drawLine(Image& image, Point2 a, Point2 b, double width, const Rgb& c) {
    const double r = 0.5 * width;
    const int x0 = std::max(0, int(std::floor(std::min(a[0], b[0]) - r - 1)));
    const int x1 = std::min(image.width() - 1, int(std::ceil(std::max(a[0], b[0]) + r + 1)));
    const int y0 = std::max(0, int(std::floor(std::min(a[1], b[1]) - r - 1)));
    const int y1 = std::min(image.height() - 1, int(std::ceil(std::max(a[1], b[1]) + r + 1)));
    const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const double px = x + 0.5 - a[0], py = y + 0.5 - a[1];
            const double t = len2 > 0 ? std::clamp((px * dx + py * dy) / len2, 0.0, 1.0) : 0.0;
            const double d = std::hypot(px - t * dx, py - t * dy);
            image.blend(x, y, c, float(std::clamp(r + 0.5 - d, 0.0, 1.0)));
        }
    }
}

void drawPolyline(Image& image, std::span<const Point2> points, bool closed, double width, const Rgb& c) {
    for (size_t i = 0; i + 1 < points.size(); ++i) drawLine(image, points[i], points[i + 1], width, c);
    if (closed && points.size() > 2) drawLine(image, points.back(), points.front(), width, c);
}

namespace {

// An axis-aligned rectangle with fractional coverage at its borders.
void fillRect(Image& image, double x0, double y0, double x1, double y1, const Rgb& c) {
    for (int y = std::max(0, int(std::floor(y0))); y < std::min(image.height(), int(std::ceil(y1))); ++y) {
        const double fy = std::min(y1, y + 1.0) - std::max(y0, double(y));
        for (int x = std::max(0, int(std::floor(x0))); x < std::min(image.width(), int(std::ceil(x1))); ++x) {
            const double fx = std::min(x1, x + 1.0) - std::max(x0, double(x));
            image.blend(x, y, c, float(fx * fy));
        }
    }
}

constexpr double kLineHeight = 12;  // stb_easy_font's line spacing in font units

}  // namespace

double textWidth(std::string_view text, double scale) {
    const std::string s(text);
    return stb_easy_font_width(const_cast<char*>(s.c_str())) * scale;
}

double textHeight(double scale) {
    return 7 * scale;
}

std::pair<std::string, std::string> breakToFit(std::string_view text, double scale, double width) {
    if (textWidth(text, scale) <= width) return {std::string(text), ""};
    for (size_t at = text.size(); at-- > 1;) {
        if (text[at] != ' ' || (text[at - 1] != ',' && text[at - 1] != ';' && text[at - 1] != ':')) continue;
        if (textWidth(text.substr(0, at), scale) <= width)
            return {std::string(text.substr(0, at)), std::string(text.substr(at + 1))};
    }
    return {std::string(text), ""};
}

std::vector<std::string> wrapToFit(std::string_view text, double scale, double width, bool atSpaces) {
    std::vector<std::string> lines;
    for (std::string rest(text); !rest.empty();) {
        auto [first, second] = breakToFit(rest, scale, width);
        // No separator that fits: the last space that does or, without spaces as breaks, the first separator
        // (the part too wide alone on its line, not the parts after it).
        for (size_t at = first.size(); atSpaces && textWidth(first, scale) > width && at-- > 1;)
            if (first[at] == ' ' && textWidth(std::string_view(first).substr(0, at), scale) <= width) {
                second = first.substr(at + 1) + (second.empty() ? "" : " " + second);
                first.resize(at);
            }
        for (size_t at = 1; !atSpaces && textWidth(first, scale) > width && at + 1 < first.size(); ++at)
            if (first[at] == ' ' && (first[at - 1] == ',' || first[at - 1] == ';' || first[at - 1] == ':')) {
                second = first.substr(at + 1) + (second.empty() ? "" : " " + second);
                first.resize(at);
            }
        lines.push_back(std::move(first));
        rest = std::move(second);
    }
    return lines;
}

void drawText(Image& image, double x, double y, std::string_view text, double scale, const Rgb& c,
              Align align) {
    size_t start = 0;
    for (int line = 0; start <= text.size(); ++line) {
        const size_t end = std::min(text.find('\n', start), text.size());
        std::string s(text.substr(start, end - start));
        start = end + 1;
        double left = x;
        if (align != Align::Left) left -= textWidth(s, scale) * (align == Align::Center ? 0.5 : 1.0);
        // stb_easy_font writes 4 vertices of 16 bytes per quad, up to about 15 quads per character.
        std::vector<char> buffer(s.size() * 1024 + 64);
        const int quads = stb_easy_font_print(0, 0, s.data(), nullptr, buffer.data(), int(buffer.size()));
        for (int q = 0; q < quads; ++q) {
            float v[16];
            std::memcpy(v, buffer.data() + q * 64, sizeof v);
            const double qx0 = v[0], qy0 = v[1], qx1 = v[8],
                         qy1 = v[9];  // vertices 0 and 2: opposite corners
            fillRect(image, left + qx0 * scale, y + (line * kLineHeight + qy0) * scale, left + qx1 * scale,
                     y + (line * kLineHeight + qy1) * scale, c);
        }
    }
}

}  // namespace facetlight
