/* The job of a `make MPI=1` build (core/base/dist.h) over Open MPI. A process not started by a launcher
 * (no launcher variables in its environment) never calls MPI_Init and is a job of one, exactly as
 * the default build: Open MPI's singleton start-up would spawn a helper daemon for nothing. */
#define _GNU_SOURCE /* program_invocation_short_name */
#include "base/dist.h"
#include <errno.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static bool joined;          /* MPI_Init_thread called */
static int rank_, size_ = 1; /* of MPI_COMM_WORLD once joined */

/* The size the launcher announced: Open MPI's mpirun, PMIx and PMI-1/2 launchers (srun). */
static int launcher_size(void)
{
    const char *vars[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_SIZE", "PMI_SIZE"};
    for (size_t i = 0; i < sizeof vars / sizeof *vars; i++) {
        const char *v = getenv(vars[i]);
        if (v && *v) return atoi(v);
    }
    return getenv("PMIX_RANK") ? 2 : 0; /* PMIx without a size variable: launched, size unknown */
}

static int launcher_rank(void)
{
    const char *vars[] = {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"};
    for (size_t i = 0; i < sizeof vars / sizeof *vars; i++) {
        const char *v = getenv(vars[i]);
        if (v && *v) return atoi(v);
    }
    return 0;
}

static _Noreturn void fail(const char *what, int code)
{
    char msg[MPI_MAX_ERROR_STRING];
    int len = 0;
    MPI_Error_string(code, msg, &len);
    fprintf(stderr, "%s: MPI: %s failed: %s\n", program_invocation_short_name, what, msg);
    MPI_Abort(MPI_COMM_WORLD, 2);
    exit(2);
}

#define CHECK(call)                                                                                                    \
    do {                                                                                                               \
        int rc_ = (call);                                                                                              \
        if (rc_ != MPI_SUCCESS) fail(#call, rc_);                                                                      \
    } while (0)

void dist_init(int *argc, char ***argv)
{
    if (joined || launcher_size() < 1) return;
    int provided;
    /* SERIALIZED: the time-budgeted pass decision is taken on whichever worker thread arrives last
     * at the pass barrier (core/mc/render.c), never by two threads at once. */
    CHECK(MPI_Init_thread(argc, argv, MPI_THREAD_SERIALIZED, &provided));
    joined = true;
    atexit(dist_finalize);
    CHECK(MPI_Comm_rank(MPI_COMM_WORLD, &rank_));
    CHECK(MPI_Comm_size(MPI_COMM_WORLD, &size_));
    if (provided < MPI_THREAD_SERIALIZED) {
        if (rank_ == 0)
            fprintf(stderr, "%s: this MPI library provides thread level %d; the renderer needs MPI_THREAD_SERIALIZED\n",
                    program_invocation_short_name, provided);
        MPI_Finalize();
        joined = false;
        exit(2);
    }
    if (rank_ != 0) {
        if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)) {
            fprintf(stderr, "%s: rank %d: cannot silence its output: %s\n", program_invocation_short_name, rank_,
                    strerror(errno));
            MPI_Abort(MPI_COMM_WORLD, 2);
        }
    }
}

void dist_finalize(void)
{
    if (!joined) return;
    joined = false;
    int done = 0;
    MPI_Finalized(&done);
    if (!done) MPI_Finalize();
}

/* Called by every query: a program that never joined, run by a launcher with several processes,
 * would have each of them render the whole job and write the same files. */
static void refuse_if_launched(void)
{
    static bool checked;
    if (joined || checked) return;
    checked = true;
    if (launcher_size() > 1) {
        if (launcher_rank() == 0)
            fprintf(stderr,
                    "%s: not rank-aware: run it without mpirun (only bin/render splits a render over MPI ranks; "
                    "bin/ch6_equal --render scripts/mpirun-render.sh runs its renders that way)\n",
                    program_invocation_short_name);
        exit(2);
    }
}

void dist_refuse_ranks(void) { refuse_if_launched(); }

int dist_rank(void)
{
    refuse_if_launched();
    return joined ? rank_ : 0;
}

int dist_size(void)
{
    refuse_if_launched();
    return joined ? size_ : 1;
}

/* MPI counts are ints: long arrays travel in pieces. */
enum { PIECE = 1 << 28 };

void dist_sum_doubles(double *v, size_t n)
{
    if (dist_size() < 2) return;
    for (size_t i = 0; i < n; i += PIECE) {
        int c = (int)(n - i < PIECE ? n - i : PIECE);
        CHECK(MPI_Allreduce(MPI_IN_PLACE, v + i, c, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD));
    }
}

void dist_sum_longs(long *v, size_t n)
{
    if (dist_size() < 2) return;
    for (size_t i = 0; i < n; i += PIECE) {
        int c = (int)(n - i < PIECE ? n - i : PIECE);
        CHECK(MPI_Allreduce(MPI_IN_PLACE, v + i, c, MPI_LONG, MPI_SUM, MPI_COMM_WORLD));
    }
}

bool dist_bcast_bool(bool v)
{
    if (dist_size() < 2) return v;
    int x = v;
    CHECK(MPI_Bcast(&x, 1, MPI_INT, 0, MPI_COMM_WORLD));
    return x != 0;
}

double dist_max_double(double v)
{
    if (dist_size() < 2) return v;
    CHECK(MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD));
    return v;
}

/* The buffers are raw bytes: every rank runs the same build on the same kind of machine. */
static void send_bufs(const struct dist_buf *bufs, int nbufs, int to)
{
    for (int b = 0; b < nbufs; b++)
        for (size_t i = 0; i < bufs[b].bytes; i += PIECE) {
            size_t c = bufs[b].bytes - i < PIECE ? bufs[b].bytes - i : PIECE;
            CHECK(MPI_Send((char *)bufs[b].p + i, (int)c, MPI_BYTE, to, b, MPI_COMM_WORLD));
        }
}

static void recv_bufs(const struct dist_buf *bufs, int nbufs, int from)
{
    for (int b = 0; b < nbufs; b++)
        for (size_t i = 0; i < bufs[b].bytes; i += PIECE) {
            size_t c = bufs[b].bytes - i < PIECE ? bufs[b].bytes - i : PIECE;
            CHECK(MPI_Recv((char *)bufs[b].p + i, (int)c, MPI_BYTE, from, b, MPI_COMM_WORLD, MPI_STATUS_IGNORE));
        }
}

void dist_chain(const struct dist_buf *bufs, int nbufs, void (*add)(void *ctx), void *ctx)
{
    int n = dist_size(), r = dist_rank();
    if (n < 2) {
        add(ctx);
        return;
    }
    if (r > 0) recv_bufs(bufs, nbufs, r - 1);
    add(ctx);
    send_bufs(bufs, nbufs, (r + 1) % n);
    if (r == 0) recv_bufs(bufs, nbufs, n - 1);
}
