#include "pictures/colour_picture.h"

#include <algorithm>

#include "pictures/face_up_frame.h"
#include "scene/scene.h"
#include "util/number_text.h"

namespace facetlight {
namespace {

constexpr int kTitleHeight = 52;
constexpr int kLegendRow = 20;
const Rgb kInk{0.1f, 0.1f, 0.1f};
// Off the stone: a neutral mid grey (L* 50), against which a colour is neither lifted nor dulled.
constexpr double kBackgroundY = 0.1842;

std::string figure(const char* name, const ColourFigure& f) {
    return std::string(name) + " " + formatNumber("%.1f", f.mean) + " +- " +
           formatNumber("%.2f", f.meanError) + " (spread " + formatNumber("%.1f", f.spread) + ")";
}

std::string percent(const char* name, const ColourShare& s) {
    return std::string(name) + " " + formatNumber("%.1f", 100 * s.share) + " +- " +
           formatNumber("%.1f", 100 * s.standardError) + " %";
}

// A legend line at (x, y), as large as fits the picture's width.
void legendText(Image& image, double x, double y, const std::string& text) {
    drawText(image, x, y, text, std::min(1.5, (image.width() - 5 - x) / std::max(1.0, textWidth(text, 1))),
             kInk);
}

Rgb display(const Vec3& xyz) {
    const Vec3 rgb = xyzToLinearSrgb(xyz);
    return {float(srgbEncode(rgb.x)), float(srgbEncode(rgb.y)), float(srgbEncode(rgb.z))};
}

}  // namespace

std::string colourTitle(const Stone& stone, const TraceSettings& settings) {
    return "True colour face-up: " + stone.name + ", " + chooseMaterial(settings, stone).material.name() +
           ", " + formatNumber("%g", settings.sizeMm) + " mm";
}

std::string colourSummary(const ColourView& v) {
    return figure("L*", v.L) + ", " + figure("a*", v.a) + ", " + figure("b*", v.b) + ", " +
           figure("C*ab", v.chroma) + "; " + percent("windowed", v.windowed) + ", " +
           percent(("extinct (L* < " + formatNumber("%g", v.extinctBelowL) + ")").c_str(), v.extinct) + ", " +
           percent(("saturated (C*ab > " + formatNumber("%g", v.saturatedAboveC) + ")").c_str(), v.saturated);
}

Image colourPicture(const ColourView& v, const std::string& title) {
    const int n = v.size, s = std::max(1, 480 / std::max(n, 1)), side = n * s;
    const int width = std::max(side + 20, 720);
    Image image(width, kTitleHeight + side + 12 + 4 * kLegendRow, {1, 1, 1});
    const int left = (width - side) / 2, top = kTitleHeight;
    const Vec3 background = v.white * kBackgroundY;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const size_t k = size_t(y) * size_t(n) + size_t(x);
            // Rays that missed the stone show the background, so the outline is anti-aliased.
            const double off = double(v.samples - v.stoneRays[k]) / double(v.samples);
            const Rgb c = display(v.xyz[k] + background * off);
            for (int dy = 0; dy < s; ++dy)
                for (int dx = 0; dx < s; ++dx) image.at(left + x * s + dx, top + y * s + dy) = c;
        }
    drawTitleBlock(image, title, colourSummary(v), 1.4, 14);
    const double y0 = top + side + 10;
    drawScaleBar(image, y0, 2 * v.halfWidthMm, side / (2 * v.halfWidthMm), v.sizeMm);
    // The legend: the lighting, and the stone's mean colour as a swatch.
    const std::string light =
        "CIE illuminant " + std::string(kIlluminantNames.name(v.illuminant)) + " dome, head cone " +
        formatNumber("%g", v.headConeDeg) + " deg dark, ground reflectance " + formatNumber("%g", v.ground) +
        "; sRGB without white balance" + (v.absorbs ? "" : "; the material absorbs nothing");
    legendText(image, 10, y0 + kLegendRow + 3, light);
    const double y = y0 + 2 * kLegendRow;
    const Point2 box[4] = {Point2{10, y}, Point2{40, y}, Point2{40, y + 16}, Point2{10, y + 16}};
    fillPolygon(image, box, display(v.meanXyz));
    drawPolyline(image, box, true, 1, kInk);
    legendText(image, 48, y + 3,
               "mean colour of the face-up area: L* " + formatNumber("%.1f", v.meanLab.L) + ", a* " +
                   formatNumber("%.1f", v.meanLab.a) + ", b* " + formatNumber("%.1f", v.meanLab.b) + " (" +
                   std::to_string(v.pixels) + " pixels x " + std::to_string(v.samples) + " paths x " +
                   std::to_string(v.wavelengths) + " wavelengths)");
    return image;
}

}  // namespace facetlight
