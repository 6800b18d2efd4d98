/*
 * slvs.h for loci: the C interface of SolveSpace 3.1's constraint solver library (libslvs),
 * implemented by loci's `libloci_slvs`.
 *
 * Names, numbers and struct layouts are those of libslvs 3.1, so a program written for
 * libslvs compiles and links against loci unchanged. What loci adds is marked "loci extension";
 * a program that must also build against libslvs can test for LOCI_SLVS before using it.
 *
 * Memory: the caller owns every array. Slvs_Solve reads params, entities and constraints and
 * writes only param[].val, failed[], faileds, dof and result.
 */
#ifndef LOCI_SLVS_H
#define LOCI_SLVS_H

/* libslvs's include guard, so that a second slvs.h on the include path is a no-op. */
#ifndef __SLVS_H
#define __SLVS_H

#include <stdint.h>
#include <string.h> /* memset, used by the inline constructors below */

#if defined(_WIN32) && !defined(DLL)
#  ifdef EXPORT_DLL
#    define DLL __declspec(dllexport)
#  else
#    define DLL __declspec(dllimport)
#  endif
#elif !defined(DLL)
#  define DLL
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* loci extension: defined when this header is loci's. */
#define LOCI_SLVS 1

/* Handles: non-zero 32-bit numbers, unique within their kind. 0 means "none". */
typedef uint32_t Slvs_hParam;
typedef uint32_t Slvs_hEntity;
typedef uint32_t Slvs_hConstraint;
typedef uint32_t Slvs_hGroup;

/* In the wrkpl field: the object is not in a workplane but free in 3D. */
#define SLVS_FREE_IN_3D 0

/* One real number. Parameters of the group being solved are unknowns; others are constants. */
typedef struct {
    Slvs_hParam h;
    Slvs_hGroup group;
    double      val;
} Slvs_Param;

/* Entity types. */
#define SLVS_E_POINT_IN_3D   50000
#define SLVS_E_POINT_IN_2D   50001
#define SLVS_E_NORMAL_IN_3D  60000
#define SLVS_E_NORMAL_IN_2D  60001
#define SLVS_E_DISTANCE      70000
#define SLVS_E_WORKPLANE     80000
#define SLVS_E_LINE_SEGMENT  80001
#define SLVS_E_CUBIC         80002
#define SLVS_E_CIRCLE        80003
#define SLVS_E_ARC_OF_CIRCLE 80004

/* A point, normal, distance, workplane, line, cubic, circle or arc. Which of point[], normal,
 * distance and param[] matter depends on type (see the Slvs_Make* constructors). */
typedef struct {
    Slvs_hEntity h;
    Slvs_hGroup  group;
    int          type;
    Slvs_hEntity wrkpl;
    Slvs_hEntity point[4];
    Slvs_hEntity normal;
    Slvs_hEntity distance;
    Slvs_hParam  param[4];
} Slvs_Entity;

/* Constraint types. */
#define SLVS_C_POINTS_COINCIDENT   100000
#define SLVS_C_PT_PT_DISTANCE      100001
#define SLVS_C_PT_PLANE_DISTANCE   100002
#define SLVS_C_PT_LINE_DISTANCE    100003
#define SLVS_C_PT_FACE_DISTANCE    100004
#define SLVS_C_PT_IN_PLANE         100005
#define SLVS_C_PT_ON_LINE          100006
#define SLVS_C_PT_ON_FACE          100007
#define SLVS_C_EQUAL_LENGTH_LINES  100008
#define SLVS_C_LENGTH_RATIO        100009
#define SLVS_C_EQ_LEN_PT_LINE_D    100010
#define SLVS_C_EQ_PT_LN_DISTANCES  100011
#define SLVS_C_EQUAL_ANGLE         100012
#define SLVS_C_EQUAL_LINE_ARC_LEN  100013
#define SLVS_C_SYMMETRIC           100014
#define SLVS_C_SYMMETRIC_HORIZ     100015
#define SLVS_C_SYMMETRIC_VERT      100016
#define SLVS_C_SYMMETRIC_LINE      100017
#define SLVS_C_AT_MIDPOINT         100018
#define SLVS_C_HORIZONTAL          100019
#define SLVS_C_VERTICAL            100020
#define SLVS_C_DIAMETER            100021
#define SLVS_C_PT_ON_CIRCLE        100022
#define SLVS_C_SAME_ORIENTATION    100023
#define SLVS_C_ANGLE               100024
#define SLVS_C_PARALLEL            100025
#define SLVS_C_PERPENDICULAR       100026
#define SLVS_C_ARC_LINE_TANGENT    100027
#define SLVS_C_CUBIC_LINE_TANGENT  100028
#define SLVS_C_EQUAL_RADIUS        100029
#define SLVS_C_PROJ_PT_DISTANCE    100030
#define SLVS_C_WHERE_DRAGGED       100031
#define SLVS_C_CURVE_CURVE_TANGENT 100032
#define SLVS_C_LENGTH_DIFFERENCE   100033
#define SLVS_C_ARC_ARC_LEN_RATIO   100034
#define SLVS_C_ARC_LINE_LEN_RATIO  100035
#define SLVS_C_ARC_ARC_DIFFERENCE  100036
#define SLVS_C_ARC_LINE_DIFFERENCE 100037

/* A geometric condition; which fields matter depends on type. valA is a distance, an angle in
 * degrees or a ratio; other and other2 are flags (supplementary angle, other end of a curve). */
typedef struct {
    Slvs_hConstraint h;
    Slvs_hGroup      group;
    int              type;
    Slvs_hEntity     wrkpl;
    double           valA;
    Slvs_hEntity     ptA;
    Slvs_hEntity     ptB;
    Slvs_hEntity     entityA;
    Slvs_hEntity     entityB;
    Slvs_hEntity     entityC;
    Slvs_hEntity     entityD;
    int              other;
    int              other2;
} Slvs_Constraint;

/* Result codes of Slvs_Solve, as libslvs 3.1. */
#define SLVS_RESULT_OKAY              0
#define SLVS_RESULT_INCONSISTENT      1
#define SLVS_RESULT_DIDNT_CONVERGE    2
#define SLVS_RESULT_TOO_MANY_UNKNOWNS 3 /* never returned by loci: it has no size limit */

/* loci extension: the input could not be read as a model (a null array with a non-zero count,
 * a negative count, a dangling handle, an unknown type, a NaN or infinite value, a constraint
 * without the workplane its type needs ...). failed[] holds the offending constraint when there
 * is one (faileds = 1), else faileds = 0; dof = -1; no parameter is written.
 * Loci_Slvs_LastError() describes the problem. */
#define LOCI_SLVS_RESULT_INVALID_INPUT 100
/* loci extension: an internal error in loci (a bug; please report it with the input). Nothing
 * is written but result, faileds = 0 and dof = -1. */
#define LOCI_SLVS_RESULT_INTERNAL_ERROR 101

typedef struct {
    /* Input: the model. param[] is also output: the solved values are written back to val. */
    Slvs_Param      *param;
    int              params;
    Slvs_Entity     *entity;
    int              entities;
    Slvs_Constraint *constraint;
    int              constraints;

    /* Input: up to four parameters the user is dragging; they move as little as possible.
     * Unused slots are 0. */
    Slvs_hParam      dragged[4];

    /* Input: non-zero to name the constraints that make the solve fail. */
    int              calculateFaileds;

    /* Output: the caller allocates failed[] and puts its length in faileds; the solver writes
     * up to that many constraint handles and sets faileds to the number it found. With a null
     * failed[], faileds is left alone. */
    Slvs_hConstraint *failed;
    int              faileds;

    /* Output: degrees of freedom left. */
    int              dof;

    /* Output: one of SLVS_RESULT_* (or a LOCI_SLVS_RESULT_* extension code). */
    int              result;
} Slvs_System;

/* Solves group hg of sys: parameters of group hg are unknowns, all others stay as they are.
 *
 * As libslvs 3.1: SLVS_RESULT_OKAY when every constraint holds and none is redundant (values
 * written); SLVS_RESULT_INCONSISTENT when constraints conflict (values not written) and also
 * when every constraint holds but some are redundant (values written); failed[] names them.
 * SLVS_RESULT_DIDNT_CONVERGE when no solution was found (values not written). */
DLL void Slvs_Solve(Slvs_System *sys, Slvs_hGroup hg);

/* The basis vectors U, V and N of the rotation given by the unit quaternion (qw, qx, qy, qz). */
DLL void Slvs_QuaternionU(double qw, double qx, double qy, double qz,
                          double *x, double *y, double *z);
DLL void Slvs_QuaternionV(double qw, double qx, double qy, double qz,
                          double *x, double *y, double *z);
DLL void Slvs_QuaternionN(double qw, double qx, double qy, double qz,
                          double *x, double *y, double *z);

/* The unit quaternion whose rotation takes the x and y axes to the orthonormal vectors u, v. */
DLL void Slvs_MakeQuaternion(double ux, double uy, double uz,
                             double vx, double vy, double vz,
                             double *qw, double *qx, double *qy, double *qz);

/* loci extension: copies a description of the last LOCI_SLVS_RESULT_* failure on this thread
 * into buf (at most len bytes, NUL-terminated) and returns the length of the full message
 * (0 when the last solve on this thread had no such failure). */
DLL int Loci_Slvs_LastError(char *buf, int len);

/* Constructors that fill the structs, zeroing every field the type does not use. */

static inline Slvs_Param Slvs_MakeParam(Slvs_hParam h, Slvs_hGroup group, double val)
{
    Slvs_Param p;
    p.h = h;
    p.group = group;
    p.val = val;
    return p;
}

/* An entity of `type` with every reference empty. (Not in libslvs: a helper for the ones below.) */
static inline Slvs_Entity Loci_Slvs_BlankEntity(Slvs_hEntity h, Slvs_hGroup group, int type,
                                                Slvs_hEntity wrkpl)
{
    Slvs_Entity e;
    memset(&e, 0, sizeof e);
    e.h = h;
    e.group = group;
    e.type = type;
    e.wrkpl = wrkpl;
    return e;
}

static inline Slvs_Entity Slvs_MakePoint2d(Slvs_hEntity h, Slvs_hGroup group, Slvs_hEntity wrkpl,
                                           Slvs_hParam u, Slvs_hParam v)
{
    Slvs_Entity e = Loci_Slvs_BlankEntity(h, group, SLVS_E_POINT_IN_2D, wrkpl);
    e.param[0] = u;
    e.param[1] = v;
    return e;
}

static inline Slvs_Entity Slvs_MakePoint3d(Slvs_hEntity h, Slvs_hGroup group,
                                           Slvs_hParam x, Slvs_hParam y, Slvs_hParam z)
{
    Slvs_Entity e = Loci_Slvs_BlankEntity(h, group, SLVS_E_POINT_IN_3D, SLVS_FREE_IN_3D);
    e.param[0] = x;
    e.param[1] = y;
    e.param[2] = z;
    return e;
}

static inline Slvs_Entity Slvs_MakeNormal3d(Slvs_hEntity h, Slvs_hGroup group,
                                            Slvs_hParam qw, Slvs_hParam qx,
                                            Slvs_hParam qy, Slvs_hParam qz)
{
    Slvs_Entity e = Loci_Slvs_BlankEntity(h, group, SLVS_E_NORMAL_IN_3D, SLVS_FREE_IN_3D);
    e.param[0] = qw;
    e.param[1] = qx;
    e.param[2] = qy;
    e.param[3] = qz;
    return e;
}

static inline Slvs_Entity Slvs_MakeNormal2d(Slvs_hEntity h, Slvs_hGroup group, Slvs_hEntity wrkpl)
{
    return Loci_Slvs_BlankEntity(h, group, SLVS_E_NORMAL_IN_2D, wrkpl);
}

static inline Slvs_Entity Slvs_MakeDistance(Slvs_hEntity h, Slvs_hGroup group, Slvs_hEntity wrkpl,
                                            Slvs_hParam d)
{
    Slvs_Entity e = Loci_Slvs_BlankEntity(h, group, SLVS_E_DISTANCE, wrkpl);
    e.param[0] = d;
    return e;
}

static inline Slvs_Entity Slvs_MakeLineSegment(Slvs_hEntity h, Slvs_hGroup group,
                                               Slvs_hEntity wrkpl,
                                               Slvs_hEntity ptA, Slvs_hEntity ptB)
{
    Slvs_Entity e = Loci_Slvs_BlankEntity(h, group, SLVS_E_LINE_SEGMENT, wrkpl);
    e.point[0] = ptA;
    e.point[1] = ptB;
    return e;
}

static inline Slvs_Entity Slvs_MakeCubic(Slvs_hEntity h, Slvs_hGroup group, Slvs_hEntity wrkpl,
                                         Slvs_hEntity pt0, Slvs_hEntity pt1,
                                         Slvs_hEntity pt2, Slvs_hEntity pt3)
{
    Slvs_Entity e = Loci_Slvs_BlankEntity(h, group, SLVS_E_CUBIC, wrkpl);
    e.point[0] = pt0;
    e.point[1] = pt1;
    e.point[2] = pt2;
    e.point[3] = pt3;
    return e;
}

/* An arc in wrkpl about `center`, counter-clockwise from `start` to `end`. */
static inline Slvs_Entity Slvs_MakeArcOfCircle(Slvs_hEntity h, Slvs_hGroup group,
                                               Slvs_hEntity wrkpl, Slvs_hEntity normal,
                                               Slvs_hEntity center,
                                               Slvs_hEntity start, Slvs_hEntity end)
{
    Slvs_Entity e = Loci_Slvs_BlankEntity(h, group, SLVS_E_ARC_OF_CIRCLE, wrkpl);
    e.normal = normal;
    e.point[0] = center;
    e.point[1] = start;
    e.point[2] = end;
    return e;
}

static inline Slvs_Entity Slvs_MakeCircle(Slvs_hEntity h, Slvs_hGroup group, Slvs_hEntity wrkpl,
                                          Slvs_hEntity center, Slvs_hEntity normal,
                                          Slvs_hEntity radius)
{
    Slvs_Entity e = Loci_Slvs_BlankEntity(h, group, SLVS_E_CIRCLE, wrkpl);
    e.point[0] = center;
    e.normal = normal;
    e.distance = radius;
    return e;
}

static inline Slvs_Entity Slvs_MakeWorkplane(Slvs_hEntity h, Slvs_hGroup group,
                                             Slvs_hEntity origin, Slvs_hEntity normal)
{
    Slvs_Entity e = Loci_Slvs_BlankEntity(h, group, SLVS_E_WORKPLANE, SLVS_FREE_IN_3D);
    e.point[0] = origin;
    e.normal = normal;
    return e;
}

/* A constraint; entityC, entityD, other and other2 start at 0 (set them afterwards if needed). */
static inline Slvs_Constraint Slvs_MakeConstraint(Slvs_hConstraint h, Slvs_hGroup group, int type,
                                                  Slvs_hEntity wrkpl, double valA,
                                                  Slvs_hEntity ptA, Slvs_hEntity ptB,
                                                  Slvs_hEntity entityA, Slvs_hEntity entityB)
{
    Slvs_Constraint c;
    memset(&c, 0, sizeof c);
    c.h = h;
    c.group = group;
    c.type = type;
    c.wrkpl = wrkpl;
    c.valA = valA;
    c.ptA = ptA;
    c.ptB = ptB;
    c.entityA = entityA;
    c.entityB = entityB;
    return c;
}

#ifdef __cplusplus
}
#endif

#endif /* __SLVS_H */
#endif /* LOCI_SLVS_H */
