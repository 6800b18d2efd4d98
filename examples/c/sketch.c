/* A small sketch solved through slvs.h: a right triangle with its legs dimensioned, and a
 * circle centred on the hypotenuse's midpoint passing through the right-angle corner.
 *
 * Build (from the repository root, after `cargo build --release -p loci-slvs`):
 *   cc -I crates/loci-slvs/include examples/c/sketch.c -L target/release -lloci_slvs \
 *      -Wl,-rpath,"$PWD/target/release" -lm -o sketch && ./sketch
 * The same file builds unchanged against SolveSpace's libslvs: cc examples/c/sketch.c -lslvs -lm
 */
#include <stdio.h>
#include <string.h>
#include <slvs.h>

static Slvs_Param param[64];
static Slvs_Entity entity[32];
static Slvs_Constraint constraint[32];
static Slvs_hConstraint failed[32];

int main(void)
{
    Slvs_System sys;
    memset(&sys, 0, sizeof sys);
    sys.param = param;
    sys.entity = entity;
    sys.constraint = constraint;
    sys.failed = failed;
    sys.faileds = 32;
    sys.calculateFaileds = 1;

    /* Group 1: the xy plane, which the solver will not move. */
    double qw, qx, qy, qz;
    Slvs_MakeQuaternion(1, 0, 0, 0, 1, 0, &qw, &qx, &qy, &qz);
    param[sys.params++] = Slvs_MakeParam(1, 1, 0);
    param[sys.params++] = Slvs_MakeParam(2, 1, 0);
    param[sys.params++] = Slvs_MakeParam(3, 1, 0);
    entity[sys.entities++] = Slvs_MakePoint3d(101, 1, 1, 2, 3);
    param[sys.params++] = Slvs_MakeParam(4, 1, qw);
    param[sys.params++] = Slvs_MakeParam(5, 1, qx);
    param[sys.params++] = Slvs_MakeParam(6, 1, qy);
    param[sys.params++] = Slvs_MakeParam(7, 1, qz);
    entity[sys.entities++] = Slvs_MakeNormal3d(102, 1, 4, 5, 6, 7);
    entity[sys.entities++] = Slvs_MakeWorkplane(200, 1, 101, 102);

    /* Group 2: the sketch, drawn roughly. */
    const double rough[4][2] = {{1, -1}, {28, 3}, {2, 37}, {14, 19}};
    for (int i = 0; i < 4; i++) {
        param[sys.params++] = Slvs_MakeParam(11 + 2 * i, 2, rough[i][0]);
        param[sys.params++] = Slvs_MakeParam(12 + 2 * i, 2, rough[i][1]);
        entity[sys.entities++] = Slvs_MakePoint2d(301 + i, 2, 200, 11 + 2 * i, 12 + 2 * i);
    }
    entity[sys.entities++] = Slvs_MakeLineSegment(401, 2, 200, 301, 302); /* a-b */
    entity[sys.entities++] = Slvs_MakeLineSegment(402, 2, 200, 301, 303); /* a-c */
    entity[sys.entities++] = Slvs_MakeLineSegment(403, 2, 200, 302, 303); /* b-c */
    entity[sys.entities++] = Slvs_MakeNormal2d(501, 2, 200);
    param[sys.params++] = Slvs_MakeParam(21, 2, 20);
    entity[sys.entities++] = Slvs_MakeDistance(502, 2, 200, 21);
    entity[sys.entities++] = Slvs_MakeCircle(503, 2, 200, 304, 501, 502);

    int n = 0;
    /* a at the origin, a-b horizontal 30 long, a-c perpendicular 40 long. */
    constraint[n++] = Slvs_MakeConstraint(1, 2, SLVS_C_POINTS_COINCIDENT, 200, 0, 301, 101, 0, 0);
    constraint[n++] = Slvs_MakeConstraint(2, 2, SLVS_C_HORIZONTAL, 200, 0, 0, 0, 401, 0);
    constraint[n++] = Slvs_MakeConstraint(3, 2, SLVS_C_PT_PT_DISTANCE, 200, 30, 301, 302, 0, 0);
    constraint[n++] = Slvs_MakeConstraint(4, 2, SLVS_C_PERPENDICULAR, 200, 0, 0, 0, 401, 402);
    constraint[n++] = Slvs_MakeConstraint(5, 2, SLVS_C_PT_PT_DISTANCE, 200, 40, 301, 303, 0, 0);
    /* The circle: centred on the hypotenuse's midpoint, through a. */
    constraint[n++] = Slvs_MakeConstraint(6, 2, SLVS_C_AT_MIDPOINT, 200, 0, 304, 0, 403, 0);
    constraint[n++] = Slvs_MakeConstraint(7, 2, SLVS_C_PT_ON_CIRCLE, 200, 0, 301, 0, 503, 0);
    sys.constraints = n;

    Slvs_Solve(&sys, 2);

    if (sys.result != SLVS_RESULT_OKAY) {
        printf("solve failed: result %d, %d constraint(s) to look at:", sys.result, sys.faileds);
        for (int i = 0; i < sys.faileds; i++) printf(" %u", failed[i]);
        printf("\n");
        return 1;
    }
    printf("solved, %d degrees of freedom left\n", sys.dof);
    const char *names = "abcm";
    for (int i = 0; i < 4; i++)
        printf("  %c = (%.3f, %.3f)\n", names[i], param[7 + 2 * i].val, param[8 + 2 * i].val);
    printf("  circle radius = %.3f\n", param[15].val);
    return 0;
}
