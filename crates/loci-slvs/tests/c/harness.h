/* A small harness for building Slvs_System models by hand and printing what Slvs_Solve did,
 * one line per system, so that two builds of the same program (against loci and against
 * libslvs) can be compared line by line.
 *
 * Output line: name|result|dof|faileds|f1,f2,...|h=val,h=val,...   (params of the solved group)
 * A system whose solve crashes prints name|CRASH|signal.
 */
#include <string.h>
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <sys/wait.h>
#include <unistd.h>
#include <slvs.h>

#define MAXN 4096

static Slvs_Param P_[MAXN];
static Slvs_Entity E_[MAXN];
static Slvs_Constraint C_[MAXN];
static Slvs_hConstraint F_[MAXN];
static Slvs_System S_;
static Slvs_hParam next_param;
static Slvs_hEntity next_entity;
static Slvs_hConstraint next_constraint;
/* The group new objects go in, and the workplane new 2D objects and constraints use
 * (0: free in 3D). */
static Slvs_hGroup G;
static Slvs_hEntity W;
/* Settings for the next solve. */
static int CF;
static int FAILED_ROOM;

#define XY 200 /* the xy plane, in group 1 */

static Slvs_hParam par(double v)
{
    Slvs_hParam h = next_param++;
    P_[S_.params++] = Slvs_MakeParam(h, G, v);
    return h;
}
static Slvs_hEntity add_entity(Slvs_Entity e)
{
    E_[S_.entities++] = e;
    return e.h;
}
static Slvs_hEntity pt2(double u, double v)
{
    Slvs_hEntity h = next_entity++;
    Slvs_hParam a = par(u), b = par(v);
    return add_entity(Slvs_MakePoint2d(h, G, W, a, b));
}
static Slvs_hEntity pt3(double x, double y, double z)
{
    Slvs_hEntity h = next_entity++;
    Slvs_hParam a = par(x), b = par(y), c = par(z);
    return add_entity(Slvs_MakePoint3d(h, G, a, b, c));
}
/* A point in the current workplane, or in 3D when there is none. */
static Slvs_hEntity pt(double x, double y, double z)
{
    return W ? pt2(x, y) : pt3(x, y, z);
}
static Slvs_hEntity ln(Slvs_hEntity a, Slvs_hEntity b)
{
    return add_entity(Slvs_MakeLineSegment(next_entity++, G, W, a, b));
}
static Slvs_hEntity nrm3(double w, double x, double y, double z)
{
    Slvs_hEntity h = next_entity++;
    Slvs_hParam a = par(w), b = par(x), c = par(y), d = par(z);
    return add_entity(Slvs_MakeNormal3d(h, G, a, b, c, d));
}
static Slvs_hEntity nrm2(void)
{
    return add_entity(Slvs_MakeNormal2d(next_entity++, G, W));
}
static Slvs_hEntity dist(double r)
{
    Slvs_hEntity h = next_entity++;
    Slvs_hParam a = par(r);
    return add_entity(Slvs_MakeDistance(h, G, W, a));
}
/* A circle in the current workplane (normal from it) or in 3D with normal n. */
static Slvs_hEntity circ(Slvs_hEntity center, Slvs_hEntity n, double r)
{
    Slvs_hEntity normal = n ? n : nrm2();
    Slvs_hEntity d = dist(r);
    return add_entity(Slvs_MakeCircle(next_entity++, G, W, center, normal, d));
}
static Slvs_hEntity arc(Slvs_hEntity center, Slvs_hEntity start, Slvs_hEntity end)
{
    Slvs_hEntity n = nrm2();
    return add_entity(Slvs_MakeArcOfCircle(next_entity++, G, W, n, center, start, end));
}
static Slvs_hEntity cubic(Slvs_hEntity a, Slvs_hEntity b, Slvs_hEntity c, Slvs_hEntity d)
{
    return add_entity(Slvs_MakeCubic(next_entity++, G, W, a, b, c, d));
}
static Slvs_Constraint *con(int type, double val, Slvs_hEntity ptA, Slvs_hEntity ptB,
                            Slvs_hEntity eA, Slvs_hEntity eB)
{
    Slvs_Constraint *c = &C_[S_.constraints++];
    *c = Slvs_MakeConstraint(next_constraint++, G, type, W, val, ptA, ptB, eA, eB);
    return c;
}
/* Lock a point where it is. */
static void fix(Slvs_hEntity p)
{
    con(SLVS_C_WHERE_DRAGGED, 0, p, 0, 0, 0);
}

/* Starts a new model: the xy plane (origin and normal) in group 1; new objects go in group 2,
 * in that plane. */
static void reset(void)
{
    memset(&S_, 0, sizeof S_);
    next_param = 1;
    next_entity = 101;
    next_constraint = 1;
    CF = 1;
    FAILED_ROOM = MAXN;
    G = 1;
    W = 0;
    double qw, qx, qy, qz;
    Slvs_MakeQuaternion(1, 0, 0, 0, 1, 0, &qw, &qx, &qy, &qz);
    Slvs_hEntity o = pt3(0, 0, 0);
    Slvs_hEntity n = nrm3(qw, qx, qy, qz);
    add_entity(Slvs_MakeWorkplane(XY, 1, o, n));
    next_entity = 301;
    next_param = 11;
    G = 2;
    W = XY;
}

static void print_result(const char *name, Slvs_hGroup hg)
{
    printf("%s|%d|%d|%d|", name, S_.result, S_.dof, S_.faileds);
    for (int i = 0; i < S_.faileds && i < FAILED_ROOM; i++) printf("%u,", F_[i]);
    printf("|");
    for (int i = 0; i < S_.params; i++)
        if (P_[i].group == hg) printf("%u=%.12g,", P_[i].h, P_[i].val);
    printf("\n");
}

/* Solves group hg and prints one line; a crash inside the solver is reported, not fatal. */
static void solve_group(const char *name, Slvs_hGroup hg)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        S_.param = P_;
        S_.entity = E_;
        S_.constraint = C_;
        S_.calculateFaileds = CF;
        S_.failed = F_;
        S_.faileds = FAILED_ROOM;
        S_.dof = -99;
        S_.result = -99;
        Slvs_Solve(&S_, hg);
        print_result(name, hg);
        fflush(stdout);
        _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (WIFSIGNALED(status)) printf("%s|CRASH|%d\n", name, WTERMSIG(status));
    else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) printf("%s|CRASH|exit\n", name);
    fflush(stdout);
}

static void solve(const char *name)
{
    solve_group(name, 2);
}
