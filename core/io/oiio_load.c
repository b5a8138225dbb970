/* Opens the OpenImageIO module (oiio.so beside the executable) on first use; see oiio.h for why it
 * is not linked in. */
#include "base/util.h"
#include "io/oiio.h"
#include <dlfcn.h>
#include <limits.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static pthread_once_t once = PTHREAD_ONCE_INIT;
static bool (*module_encode)(const char *, int, int, int, const float *, unsigned char **, size_t *, char *, size_t);
static bool (*module_read)(const char *, int *, int *, int *, float **, int *, char *, size_t);
static char load_error[PATH_MAX + 256];

/* oiio.so in the directory of the running executable. */
static bool module_path(char *path, size_t size, char *err, size_t errlen)
{
    static const char name[] = "oiio.so";
    ssize_t n = readlink("/proc/self/exe", path, size - 1);
    if (n <= 0) {
        snprintf(err, errlen, "cannot find the running executable (/proc/self/exe) to locate %s", name);
        return false;
    }
    path[n] = '\0';
    char *slash = strrchr(path, '/');
    size_t dir = slash ? (size_t)(slash - path) + 1 : 0;
    if (dir + sizeof name > size) {
        snprintf(err, errlen, "executable path too long to locate %s", name);
        return false;
    }
    memcpy(path + dir, name, sizeof name);
    return true;
}

static void open_module(void)
{
    char path[PATH_MAX];
    if (!module_path(path, sizeof path, load_error, sizeof load_error)) return;
    void *h = dlopen(path, RTLD_LAZY | RTLD_LOCAL);
    if (!h) {
        snprintf(load_error, sizeof load_error, "cannot load the OpenImageIO module (%s); `make` builds it", dlerror());
        return;
    }
    /* POSIX's sanctioned way to turn dlsym's object pointer into a function pointer */
    *(void **)&module_encode = dlsym(h, "oiio_module_encode");
    *(void **)&module_read = dlsym(h, "oiio_module_read_channels");
    if (!module_encode || !module_read) {
        module_encode = NULL;
        module_read = NULL;
        snprintf(load_error, sizeof load_error, "%s lacks the oiio_module_* entry points; rebuild it with `make`",
                 path);
    }
}

static bool ready(const char *path, char *err, size_t errlen)
{
    pthread_once(&once, open_module);
    if (module_encode) return true;
    snprintf(err, errlen, "%s: %s", path, load_error);
    return false;
}

bool oiio_module_present(char *err, size_t errlen)
{
    char path[PATH_MAX];
    if (!module_path(path, sizeof path, err, errlen)) return false;
    if (access(path, R_OK) == 0) return true;
    snprintf(err, errlen, "%s: the OpenImageIO module is missing; `make` builds it", path);
    return false;
}

bool oiio_loaded(void) { return module_encode != NULL; }

bool oiio_write(const char *path, int w, int h, int nchan, const float *px, char *err, size_t errlen)
{
    pthread_once(&once, open_module);
    if (!module_encode) {
        snprintf(err, errlen, "%s", load_error);
        return false;
    }
    unsigned char *bytes = NULL;
    size_t len = 0;
    bool ok = module_encode(path, w, h, nchan, px, &bytes, &len, err, errlen) &&
              write_chunks(path, &(struct chunk){bytes, len}, 1, err, errlen);
    free(bytes);
    return ok;
}

bool oiio_read_channels(const char *path, int *w, int *h, int *nchan, float **px, int *bits, char *err, size_t errlen)
{
    return ready(path, err, errlen) && module_read(path, w, h, nchan, px, bits, err, errlen);
}
