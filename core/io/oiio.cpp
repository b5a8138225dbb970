// OpenImageIO has no C API; this file wraps the two calls the harness needs. It is built as its own
// shared object (oiio.so next to each executable), which core/io/oiio_load.c opens on the first image
// read (or oiio_write, which only tests call): Debian's OpenImageIO pulls in about 260 libraries, 120 MB resident and
// 0.2 s of dynamic linking, which runs that only compute statistics should not pay.
#include "io/oiio.h"
#include "io/texels.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

using namespace OIIO;

// Encodes into memory and leaves the file to the C side: OpenImageIO's writers do not report a
// failed write (an EXR cut short by a full disk came back as success), and there every write,
// fsync and close is checked.
extern "C" bool oiio_module_encode(const char *path, int w, int h, int nchan, const float *px, unsigned char **bytes,
                                   size_t *len, char *err, size_t errlen)
{
    Filesystem::IOVecOutput mem;
    auto out = ImageOutput::create(path, &mem);
    if (!out) {
        snprintf(err, errlen, "cannot create image writer: %s", geterror().c_str());
        return false;
    }
    std::string ext(path);
    bool eight = ext.size() >= 4 && (ext.substr(ext.size() - 4) == ".png" || ext.substr(ext.size() - 4) == ".jpg");
    ImageSpec spec(w, h, nchan, eight ? TypeDesc::UINT8 : TypeDesc::FLOAT);
    if (!eight) spec.attribute("compression", "zip");
    if (!out->open(path, spec) || !out->write_image(TypeDesc::FLOAT, px) || !out->close()) {
        snprintf(err, errlen, "%s", out->geterror().c_str());
        return false;
    }
    const std::vector<unsigned char> &buf = mem.buffer();
    *len = buf.size();
    *bytes = static_cast<unsigned char *>(malloc(*len ? *len : 1));
    if (!*bytes) {
        snprintf(err, errlen, "out of memory for %zu bytes of image", *len);
        return false;
    }
    if (*len) memcpy(*bytes, buf.data(), *len);
    return true;
}

extern "C" bool oiio_module_read_channels(const char *path, int *w, int *h, int *nchan, float **px, int *bits,
                                          char *err, size_t errlen)
{
    // Texels as stored: OpenImageIO would otherwise multiply a PNG's colour by its alpha.
    ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = ImageInput::open(path, &config);
    if (!in) {
        snprintf(err, errlen, "%s: cannot read image (%s)", path, geterror().c_str());
        return false;
    }
    const ImageSpec &spec = in->spec();
    int nc = spec.nchannels;
    if (!texels_check_size(path, spec.width, spec.height, nc, err, errlen)) return false;
    size_t n = (size_t)spec.width * spec.height * nc;
    float *buf = (float *)malloc(n * sizeof(float));
    if (!buf) abort();
    if (!in->read_image(0, 0, 0, nc, TypeDesc::FLOAT, buf)) {
        snprintf(err, errlen, "%s: %s", path, in->geterror().c_str());
        free(buf);
        return false;
    }
    in->close();
    *w = spec.width;
    *h = spec.height;
    *nchan = nc;
    *px = buf;
    if (bits) {
        TypeDesc::BASETYPE b = (TypeDesc::BASETYPE)spec.format.basetype;
        bool integer = b == TypeDesc::UINT8 || b == TypeDesc::INT8 || b == TypeDesc::UINT16 || b == TypeDesc::INT16 ||
                       b == TypeDesc::UINT32 || b == TypeDesc::INT32;
        *bits = integer ? (int)spec.format.size() * 8 : 0;
    }
    return true;
}
