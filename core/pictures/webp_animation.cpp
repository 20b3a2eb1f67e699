#include "pictures/webp_animation.h"

#include <webp/encode.h>
#include <webp/mux.h>

#include <memory>

#include "util/error.h"

namespace facetlight {

std::string encodeAnimatedWebp(std::span<const Image> frames, int frameMs) {
    if (frames.empty()) throw Error("an animation needs a frame");
    const int width = frames[0].width(), height = frames[0].height();
    WebPAnimEncoderOptions options;
    WebPConfig config;
    if (!WebPAnimEncoderOptionsInit(&options) || !WebPConfigInit(&config))
        throw Error("libwebp version mismatch");
    options.anim_params.loop_count = 0;  // forever
    config.lossless = 1;
    config.method = 0;  // fastest; the flat class colours compress well anyway
    config.quality = 25;
    const std::unique_ptr<WebPAnimEncoder, void (*)(WebPAnimEncoder*)> encoder(
        WebPAnimEncoderNew(width, height, &options), WebPAnimEncoderDelete);
    if (!encoder) throw Error("cannot start a WebP animation");
    int timestamp = 0;
    for (const Image& frame : frames) {
        if (frame.width() != width || frame.height() != height)
            throw Error("animation frames differ in size");
        WebPPicture picture;
        if (!WebPPictureInit(&picture)) throw Error("libwebp version mismatch");
        picture.use_argb = 1;
        picture.width = width;
        picture.height = height;
        const std::vector<unsigned char> rgb = toRgb8(frame);
        const bool imported = WebPPictureImportRGB(&picture, rgb.data(), width * 3);
        const bool added = imported && WebPAnimEncoderAdd(encoder.get(), &picture, timestamp, &config);
        WebPPictureFree(&picture);
        if (!added) throw Error("WebP animation: cannot add a frame");
        timestamp += frameMs;
    }
    WebPData data;
    WebPDataInit(&data);
    if (!WebPAnimEncoderAdd(encoder.get(), nullptr, timestamp, nullptr) ||
        !WebPAnimEncoderAssemble(encoder.get(), &data)) {
        throw Error("WebP animation: cannot assemble");
    }
    std::string bytes(reinterpret_cast<const char*>(data.bytes), data.size);
    WebPDataClear(&data);
    return bytes;
}

}  // namespace facetlight
