#include "pictures/colour_picture.h"

#include <algorithm>

#include "pictures/face_up_frame.h"
#include "scene/scene.h"
#include "util/number_text.h"

namespace facetlight {
namespace {

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

Rgb display(const Vec3& xyz) {
    const Vec3 rgb = xyzToLinearSrgb(xyz);
    return {float(srgbEncode(rgb.x)), float(srgbEncode(rgb.y)), float(srgbEncode(rgb.z))};
}

}  // namespace

std::string colourTitle(const Stone& stone, const TraceSettings& settings) {
    // A job's own spectrum replaces the material's colour: the title says by what.
    const std::string colouredBy = settings.absorption ? " coloured by " + origin(*settings.absorption) : "";
    return "True colour face-up: " + stone.name + ", " + chooseMaterial(settings, stone).material.name() +
           colouredBy + ", " + formatNumber("%g", settings.sizeMm) + " mm";
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
    const TitleBlock head = titleBlock(title, colourSummary(v), width);
    // The legend: the lighting, and the face-up area's light averaged, beside a swatch of it.
    const std::vector<std::string> light =
        wrapToFit("CIE illuminant " + std::string(kIlluminantNames.name(v.illuminant)) + " dome, head cone " +
                      formatNumber("%g", v.headConeDeg) + " deg dark, ground reflectance " +
                      formatNumber("%g", v.ground) + "; sRGB without white balance" +
                      (v.absorbs ? "" : "; the material absorbs nothing"),
                  2, width - 20);
    const std::vector<std::string> mean =
        wrapToFit("the face-up area's light averaged: L* " + formatNumber("%.1f", v.meanLab.L) + ", a* " +
                      formatNumber("%.1f", v.meanLab.a) + ", b* " + formatNumber("%.1f", v.meanLab.b) + "; " +
                      std::to_string(v.pixels) + " pixels x " + std::to_string(v.samples) + " paths x " +
                      std::to_string(v.wavelengths) + " wavelengths",
                  2, width - 58);
    const int legendLines = int(light.size() + std::max<size_t>(mean.size(), 2));
    Image image(width, head.height() + side + 10 + kScaleBarHeight + legendLines * kLegendLineStep + 8,
                {1, 1, 1});
    const int left = (width - side) / 2, top = head.height();
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
    drawTitleBlock(image, head);
    const double y0 = top + side + 10;
    drawScaleBar(image, y0, 2 * v.halfWidthMm, side / (2 * v.halfWidthMm), v.sizeMm);
    double y = y0 + kScaleBarHeight + 4;
    for (const std::string& line : light) {
        drawLegendLine(image, 10, y, line);
        y += kLegendLineStep;
    }
    const Point2 box[4] = {Point2{10, y}, Point2{40, y}, Point2{40, y + 2 * kLegendLineStep - 6},
                           Point2{10, y + 2 * kLegendLineStep - 6}};
    fillPolygon(image, box, display(v.meanXyz));
    drawPolyline(image, box, true, 1, kInk);
    for (size_t k = 0; k < mean.size(); ++k)
        drawLegendLine(image, 48, y + 3 + double(k) * kLegendLineStep, mean[k]);
    return image;
}

}  // namespace facetlight
