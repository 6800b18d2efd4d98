/* Benchmark: a chain of N segments in a workplane, solved through slvs.h.
 *
 * Joints coincident, every segment 10 long, the angle between neighbours fixed, the first
 * point fixed and the first segment horizontal (so the chain is fully constrained); every
 * point starts up to about 0.3 away from the answer. The same source is built against loci
 * and against libslvs by bench/run.sh.
 *
 * Usage: chain N [REPEATS]   prints: N result dof faileds best_ms mean_ms max_error
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <slvs.h>

static Slvs_Param *param;
static Slvs_Entity *entity;
static Slvs_Constraint *constraint;
static Slvs_hConstraint *failed;
static double *truth;

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

/* A deterministic perturbation in [-0.3, 0.3]. */
static double wobble(unsigned i)
{
    unsigned x = i * 2654435761u;
    x ^= x >> 15;
    return ((x % 10007) / 10006.0 - 0.5) * 0.6;
}

static void build(Slvs_System *sys, int n)
{
    memset(sys, 0, sizeof *sys);
    sys->param = param;
    sys->entity = entity;
    sys->constraint = constraint;
    sys->failed = failed;
    sys->calculateFaileds = 0;
    double qw, qx, qy, qz;
    Slvs_MakeQuaternion(1, 0, 0, 0, 1, 0, &qw, &qx, &qy, &qz);
    const double wp[7] = {0, 0, 0, qw, qx, qy, qz};
    for (int i = 0; i < 7; i++) param[sys->params++] = Slvs_MakeParam(i + 1, 1, wp[i]);
    entity[sys->entities++] = Slvs_MakePoint3d(1, 1, 1, 2, 3);
    entity[sys->entities++] = Slvs_MakeNormal3d(2, 1, 4, 5, 6, 7);
    entity[sys->entities++] = Slvs_MakeWorkplane(3, 1, 1, 2);
    Slvs_hParam hp = 10;
    Slvs_hEntity he = 10;
    Slvs_hConstraint hc = 1;
    double x = 0, y = 0, heading = 0;
    Slvs_hEntity prev_b = 0, prev_line = 0;
    for (int i = 0; i < n; i++) {
        /* The turn between segment i-1 and i alternates so the chain stays compact. */
        double turn = (i == 0) ? 0 : ((i % 2) ? 20.0 : -20.0);
        heading += turn * M_PI / 180;
        double ax = x, ay = y;
        x += 10 * cos(heading);
        y += 10 * sin(heading);
        double pts[4] = {ax, ay, x, y};
        Slvs_hEntity ends[2];
        for (int k = 0; k < 2; k++) {
            truth[hp - 10] = pts[2 * k];
            param[sys->params++] = Slvs_MakeParam(hp, 2, pts[2 * k] + wobble(hp));
            truth[hp + 1 - 10] = pts[2 * k + 1];
            param[sys->params++] = Slvs_MakeParam(hp + 1, 2, pts[2 * k + 1] + wobble(hp + 1));
            entity[sys->entities++] = Slvs_MakePoint2d(he, 2, 3, hp, hp + 1);
            ends[k] = he++;
            hp += 2;
        }
        Slvs_hEntity line = he++;
        entity[sys->entities++] = Slvs_MakeLineSegment(line, 2, 3, ends[0], ends[1]);
        constraint[sys->constraints++] =
            Slvs_MakeConstraint(hc++, 2, SLVS_C_PT_PT_DISTANCE, 3, 10, ends[0], ends[1], 0, 0);
        if (i == 0) {
            /* The first point is fixed at its (exact) place, the first segment horizontal. */
            param[sys->params - 4].val = 0;
            param[sys->params - 3].val = 0;
            constraint[sys->constraints++] =
                Slvs_MakeConstraint(hc++, 2, SLVS_C_WHERE_DRAGGED, 3, 0, ends[0], 0, 0, 0);
            constraint[sys->constraints++] =
                Slvs_MakeConstraint(hc++, 2, SLVS_C_HORIZONTAL, 3, 0, 0, 0, line, 0);
        } else {
            constraint[sys->constraints++] =
                Slvs_MakeConstraint(hc++, 2, SLVS_C_POINTS_COINCIDENT, 3, 0, prev_b, ends[0], 0, 0);
            Slvs_Constraint a =
                Slvs_MakeConstraint(hc++, 2, SLVS_C_ANGLE, 3, 20, 0, 0, prev_line, line);
            constraint[sys->constraints++] = a;
        }
        prev_b = ends[1];
        prev_line = line;
    }
    sys->faileds = sys->constraints;
}

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 100;
    int reps = argc > 2 ? atoi(argv[2]) : 5;
    param = calloc(8 + 4 * (size_t)n, sizeof *param);
    truth = calloc(4 * (size_t)n, sizeof *truth);
    entity = calloc(3 + 3 * (size_t)n, sizeof *entity);
    constraint = calloc(3 * (size_t)n + 2, sizeof *constraint);
    failed = calloc(3 * (size_t)n + 2, sizeof *failed);
    Slvs_System sys;
    double best = 1e300, total = 0;
    for (int r = 0; r < reps; r++) {
        build(&sys, n);
        double t0 = now_ms();
        Slvs_Solve(&sys, 2);
        double dt = now_ms() - t0;
        total += dt;
        if (dt < best) best = dt;
    }
    double err = 0;
    for (int i = 0; i < 4 * n; i++) {
        double e = fabs(param[7 + i].val - truth[i]);
        if (e > err) err = e;
    }
    printf("%d %d %d %d %.3f %.3f %.2e\n", n, sys.result, sys.dof, sys.faileds, best, total / reps,
           err);
    return 0;
}
