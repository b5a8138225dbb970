/* bin/render: renders a Tungsten scene with one method; writes PREFIX.exr, PREFIX.png and, for the
 * MCMC methods, PREFIX.csv with acceptance statistics (render --help). The whole run is
 * render_run.h's library call, which the figure tools make in-process; built with MPI=1 and started
 * by mpirun, its ranks share the render (core/base/dist.h) and rank 0 alone writes the outputs and
 * the summary. */
#include "base/dist.h"
#include "tools/render_run.h"

int main(int argc, char **argv)
{
    dist_init(&argc, &argv);
    return render_run(argc, argv);
}
