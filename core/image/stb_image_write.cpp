// The one translation unit that compiles stb_image_write (as pbrt-v4 does in util/stbimage.cpp).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>
