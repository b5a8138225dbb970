/* The largest inputs the renderer accepts, in one place. Anything beyond is refused with one error
 * line naming the file (and JSON path), exit status 2, before the memory for it is allocated: the
 * kernel's OOM killer is not an error message. scenes/README.md and `bin/render --help` list them;
 * the fuzz targets (tests/fuzz/) rely on them to keep every input's cost finite.
 * Plain macros: core/io/oiio.cpp includes this too. */
#ifndef INPUT_LIMITS_H
#define INPUT_LIMITS_H

/* Vertices or triangles of one mesh (.obj, .wo3): 10^8 triangles are 1.2 GB of indices and, with
 * a vertex per corner as an .obj makes them, 7 GB of positions and normals. */
#define LIMIT_MESH_ELEMS 100000000L

/* Texture and environment-map files: per side, and in texels. 16384 x 8192 (a large HDR sky) is
 * the budget: 3 floats per texel held, plus the decoder's copy with every channel of the file
 * while it is read (1.5 GB at 4 channels). */
#define LIMIT_TEXTURE_SIDE 32768
#define LIMIT_TEXTURE_TEXELS (1L << 27)
/* Channels of a texture file (the loader keeps 3), and channel values of the decoder's copy in all:
 * 64 channels of the largest size would be 34 GB, 2^29 floats are 2 GB. */
#define LIMIT_TEXTURE_CHANNELS 64
#define LIMIT_TEXTURE_VALUES (1L << 29)

/* The rendered image: per side, and in pixels (8192 x 8192). Every thread holds a framebuffer of
 * 3 doubles per pixel, 1.6 GB at this size. */
#define LIMIT_IMAGE_SIDE 32768
#define LIMIT_IMAGE_PIXELS (1L << 26)

/* A scene's JSON text. The largest committed scene is 0.2 MB; cJSON holds about 10x the text. */
#define LIMIT_SCENE_BYTES (64L << 20)

/* Integrator bounces as a scene may state them (paths are capped at MAX_PATH_LENGTH segments
 * anyway, sampler/sampler.h, with a warning). */
#define LIMIT_BOUNCES 65536

#endif
