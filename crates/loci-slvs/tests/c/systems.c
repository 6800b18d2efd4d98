/* Systems built through slvs.h, solved and printed; compiled once against loci and once
 * against SolveSpace's libslvs by tests/differential.rs, which compares the two outputs.
 *
 * Every one of the 38 constraint types appears, in a workplane and free in 3D where both
 * exist, plus dragged parameters, redundant and inconsistent systems, calculateFaileds = 0, a
 * short failed[] array, and several groups. */
#include "harness.h"

static char name_buf[128];
/* name + "_2d" or "_3d" for the tests that run both ways. */
static const char *nm(const char *base, int in3d)
{
    snprintf(name_buf, sizeof name_buf, "%s_%s", base, in3d ? "3d" : "2d");
    return name_buf;
}
/* Starts a model and selects 3D (no workplane) or the xy plane. */
static void start(int in3d)
{
    reset();
    if (in3d) W = 0;
}

/* ---- one test per constraint type, both ways where the type allows it ---- */

static void t_points_coincident(int d3)
{
    start(d3);
    Slvs_hEntity a = pt(1, 2, 3), b = pt(1, 2, 3), c = pt(4, 5, 6);
    fix(a);
    con(SLVS_C_POINTS_COINCIDENT, 0, a, b, 0, 0);
    con(SLVS_C_PT_PT_DISTANCE, 7, b, c, 0, 0);
    solve(nm("points_coincident", d3));
}

static void t_pt_pt_distance(int d3)
{
    start(d3);
    Slvs_hEntity a = pt(0, 0, 0), b = pt(10, 3, 2);
    fix(a);
    con(SLVS_C_PT_PT_DISTANCE, 25, a, b, 0, 0);
    solve(nm("pt_pt_distance", d3));
}

static void t_pt_plane_distance(void)
{
    start(1);
    Slvs_hEntity a = pt3(3, 4, 2);
    con(SLVS_C_PT_PLANE_DISTANCE, -5, a, 0, XY, 0);
    solve("pt_plane_distance");
}

static void t_pt_line_distance(int d3)
{
    start(d3);
    Slvs_hEntity a = pt(0, 0, 0), b = pt(10, 1, 0), p = pt(4, 3, 1);
    Slvs_hEntity l = ln(a, b);
    fix(a);
    fix(b);
    con(SLVS_C_PT_LINE_DISTANCE, 6, p, 0, l, 0);
    con(SLVS_C_PT_PT_DISTANCE, 8, a, p, 0, 0);
    solve(nm("pt_line_distance", d3));
}

static void t_pt_face_distance(void)
{
    start(1);
    Slvs_hEntity a = pt3(3, 4, 2);
    con(SLVS_C_PT_FACE_DISTANCE, 5, a, 0, XY, 0);
    solve("pt_face_distance");
}

static void t_pt_in_plane(void)
{
    start(1);
    Slvs_hEntity a = pt3(3, 4, 2);
    con(SLVS_C_PT_IN_PLANE, 0, a, 0, XY, 0);
    solve("pt_in_plane");
}

static void t_pt_on_line(int d3)
{
    start(d3);
    Slvs_hEntity a = pt(0, 0, 0), b = pt(10, 5, 2), p = pt(3, 4, 5);
    Slvs_hEntity l = ln(a, b);
    fix(a);
    fix(b);
    con(SLVS_C_PT_ON_LINE, 0, p, 0, l, 0);
    con(SLVS_C_PT_PT_DISTANCE, 5, a, p, 0, 0);
    solve(nm("pt_on_line", d3));
}

static void t_pt_on_face(void)
{
    start(1);
    Slvs_hEntity a = pt3(3, 4, 2);
    con(SLVS_C_PT_ON_FACE, 0, a, 0, XY, 0);
    solve("pt_on_face");
}

static void t_equal_length_lines(int d3)
{
    start(d3);
    Slvs_hEntity a = pt(0, 0, 0), b = pt(10, 0, 0), c = pt(0, 5, 1), d = pt(3, 9, 2);
    Slvs_hEntity l1 = ln(a, b), l2 = ln(c, d);
    fix(a);
    fix(b);
    fix(c);
    con(SLVS_C_EQUAL_LENGTH_LINES, 0, 0, 0, l1, l2);
    solve(nm("equal_length_lines", d3));
}

static void t_length_ratio(int d3)
{
    start(d3);
    Slvs_hEntity a = pt(0, 0, 0), b = pt(10, 0, 0), c = pt(0, 5, 1), d = pt(3, 9, 2);
    Slvs_hEntity l1 = ln(a, b), l2 = ln(c, d);
    fix(a);
    fix(b);
    fix(c);
    con(SLVS_C_LENGTH_RATIO, 2.5, 0, 0, l1, l2);
    solve(nm("length_ratio", d3));
}

static void t_length_difference(int d3)
{
    start(d3);
    Slvs_hEntity a = pt(0, 0, 0), b = pt(10, 0, 0), c = pt(0, 5, 1), d = pt(3, 9, 2);
    Slvs_hEntity l1 = ln(a, b), l2 = ln(c, d);
    fix(a);
    fix(b);
    fix(c);
    con(SLVS_C_LENGTH_DIFFERENCE, 4, 0, 0, l1, l2);
    solve(nm("length_difference", d3));
}

static void t_eq_len_pt_line_d(int d3)
{
    start(d3);
    Slvs_hEntity a = pt(0, 0, 0), b = pt(10, 0, 0), c = pt(0, 5, 1), d = pt(4, 6, 2);
    Slvs_hEntity p = pt(5, 8, 3);
    Slvs_hEntity l1 = ln(c, d), l2 = ln(a, b);
    fix(a);
    fix(b);
    fix(c);
    fix(d);
    con(SLVS_C_EQ_LEN_PT_LINE_D, 0, p, 0, l1, l2);
    solve(nm("eq_len_pt_line_d", d3));
}

static void t_eq_pt_ln_distances(int d3)
{
    start(d3);
    Slvs_hEntity a = pt(0, 0, 0), b = pt(10, 0, 0), c = pt(0, 5, 1), d = pt(10, 7, 2);
    Slvs_hEntity p = pt(3, 4, 1), q = pt(4, 10, 3);
    Slvs_hEntity l1 = ln(a, b), l2 = ln(c, d);
    fix(a);
    fix(b);
    fix(c);
    fix(d);
    fix(p);
    con(SLVS_C_EQ_PT_LN_DISTANCES, 0, p, q, l1, l2);
    solve(nm("eq_pt_ln_distances", d3));
}

static void t_equal_angle(int d3, int other)
{
    start(d3);
    Slvs_hEntity a = pt(0, 0, 0), b = pt(10, 0, 0), c = pt(0, 0, 0), d = pt(7, 7, 1);
    Slvs_hEntity e = pt(20, 0, 0), f = pt(30, 0, 0), g = pt(20, 0, 0), h = pt(28, 3, 2);
    Slvs_hEntity l1 = ln(a, b), l2 = ln(c, d), l3 = ln(e, f), l4 = ln(g, h);
    fix(a);
    fix(b);
    fix(c);
    fix(d);
    fix(e);
    fix(f);
    fix(g);
    Slvs_Constraint *k = con(SLVS_C_EQUAL_ANGLE, 0, 0, 0, l1, l2);
    k->entityC = l3;
    k->entityD = l4;
    k->other = other;
    con(SLVS_C_PT_PT_DISTANCE, 8, g, h, 0, 0);
    solve(nm(other ? "equal_angle_other" : "equal_angle", d3));
}

static void t_equal_line_arc_len(void)
{
    start(0);
    Slvs_hEntity c = pt2(0, 0), s = pt2(10, 0), e = pt2(0, 10);
    Slvs_hEntity ar = arc(c, s, e);
    Slvs_hEntity a = pt2(0, -5), b = pt2(14, -6);
    Slvs_hEntity l = ln(a, b);
    fix(c);
    fix(s);
    fix(a);
    con(SLVS_C_EQUAL_LINE_ARC_LEN, 0, 0, 0, l, ar);
    con(SLVS_C_HORIZONTAL, 0, 0, 0, l, 0);
    con(SLVS_C_VERTICAL, 0, c, e, 0, 0);
    solve("equal_line_arc_len");
}

static void t_symmetric(int d3)
{
    start(d3);
    /* A second workplane, the yz plane shifted to x = 5, as the mirror. */
    G = 1;
    Slvs_hEntity o = pt3(5, 0, 0);
    double qw, qx, qy, qz;
    Slvs_MakeQuaternion(0, 1, 0, 0, 0, 1, &qw, &qx, &qy, &qz);
    Slvs_hEntity n = nrm3(qw, qx, qy, qz);
    Slvs_hEntity mirror = add_entity(Slvs_MakeWorkplane(next_entity++, 1, o, n));
    G = 2;
    Slvs_hEntity a = pt(1, 2, 3), b = pt(8, 3, 2);
    fix(a);
    con(SLVS_C_SYMMETRIC, 0, a, b, mirror, 0);
    solve(nm("symmetric", d3));
}

static void t_symmetric_hv(int vert)
{
    start(0);
    Slvs_hEntity a = pt2(3, 4), b = pt2(-2, 5);
    fix(a);
    con(vert ? SLVS_C_SYMMETRIC_VERT : SLVS_C_SYMMETRIC_HORIZ, 0, a, b, 0, 0);
    solve(vert ? "symmetric_vert" : "symmetric_horiz");
}

static void t_symmetric_line(void)
{
    start(0);
    Slvs_hEntity a = pt2(0, 0), b = pt2(10, 10), p = pt2(2, 7), q = pt2(6, 1);
    Slvs_hEntity l = ln(a, b);
    fix(a);
    fix(b);
    fix(p);
    con(SLVS_C_SYMMETRIC_LINE, 0, p, q, l, 0);
    solve("symmetric_line");
}

static void t_at_midpoint(int d3)
{
    start(d3);
    Slvs_hEntity a = pt(0, 0, 0), b = pt(10, 4, 2), m = pt(3, 3, 3);
    Slvs_hEntity l = ln(a, b);
    fix(a);
    fix(b);
    con(SLVS_C_AT_MIDPOINT, 0, m, 0, l, 0);
    solve(nm("at_midpoint", d3));
}

static void t_horizontal_vertical(int vert, int points)
{
    start(0);
    Slvs_hEntity a = pt2(1, 2), b = pt2(9, 4);
    Slvs_hEntity l = ln(a, b);
    fix(a);
    con(SLVS_C_PT_PT_DISTANCE, 10, a, b, 0, 0);
    if (points) con(vert ? SLVS_C_VERTICAL : SLVS_C_HORIZONTAL, 0, a, b, 0, 0);
    else con(vert ? SLVS_C_VERTICAL : SLVS_C_HORIZONTAL, 0, 0, 0, l, 0);
    static char n[64];
    snprintf(n, sizeof n, "%s_%s", vert ? "vertical" : "horizontal", points ? "points" : "line");
    solve(n);
}

static void t_diameter(int which)
{
    /* 0: circle in the plane, 1: circle free in 3D with its own normal, 2: arc */
    start(which == 1);
    Slvs_hEntity c = pt(1, 2, 3);
    fix(c);
    Slvs_hEntity e;
    if (which == 2) {
        Slvs_hEntity s = pt2(6, 2), f = pt2(1, 7);
        e = arc(c, s, f);
        con(SLVS_C_HORIZONTAL, 0, c, s, 0, 0);
        con(SLVS_C_VERTICAL, 0, c, f, 0, 0);
    } else if (which == 1) {
        G = 1;
        Slvs_hEntity n = nrm3(1, 0, 0, 0);
        G = 2;
        e = circ(c, n, 4);
    } else {
        e = circ(c, 0, 4);
    }
    con(SLVS_C_DIAMETER, 13, 0, 0, e, 0);
    solve(which == 2 ? "diameter_arc" : which == 1 ? "diameter_circle_3d" : "diameter_circle");
}

static void t_pt_on_circle(int on_arc)
{
    start(0);
    Slvs_hEntity c = pt2(0, 0);
    fix(c);
    Slvs_hEntity e;
    if (on_arc) {
        Slvs_hEntity s = pt2(5, 0), f = pt2(0, 5);
        fix(s);
        e = arc(c, s, f);
    } else {
        e = circ(c, 0, 5);
        con(SLVS_C_DIAMETER, 10, 0, 0, e, 0);
    }
    Slvs_hEntity p = pt2(3, 3);
    con(SLVS_C_PT_ON_CIRCLE, 0, p, 0, e, 0);
    con(SLVS_C_HORIZONTAL, 0, c, p, 0, 0);
    solve(on_arc ? "pt_on_circle_arc" : "pt_on_circle");
}

static void t_same_orientation(void)
{
    start(1);
    Slvs_hEntity n1 = nrm3(0.9, 0.1, 0.2, 0.3);
    con(SLVS_C_SAME_ORIENTATION, 0, 0, 0, n1, XY - 98 /* the xy plane's normal, 102 */);
    solve("same_orientation");
}

static void t_angle(int d3, int other)
{
    start(d3);
    Slvs_hEntity a = pt(0, 0, 0), b = pt(10, 0, 0), c = pt(0, 0, 0), d = pt(5, 8, 1);
    Slvs_hEntity l1 = ln(a, b), l2 = ln(c, d);
    fix(a);
    fix(b);
    fix(c);
    con(SLVS_C_PT_PT_DISTANCE, 10, c, d, 0, 0);
    if (d3) con(SLVS_C_PT_PLANE_DISTANCE, 1, d, 0, XY, 0);
    Slvs_Constraint *k = con(SLVS_C_ANGLE, 30, 0, 0, l1, l2);
    k->other = other;
    solve(nm(other ? "angle_other" : "angle", d3));
}

static void t_parallel_perpendicular(int d3, int perp)
{
    start(d3);
    Slvs_hEntity a = pt(0, 0, 0), b = pt(10, 2, 1), c = pt(0, 5, 0), d = pt(8, 9, 2);
    Slvs_hEntity l1 = ln(a, b), l2 = ln(c, d);
    fix(a);
    fix(b);
    fix(c);
    con(SLVS_C_PT_PT_DISTANCE, 10, c, d, 0, 0);
    con(perp ? SLVS_C_PERPENDICULAR : SLVS_C_PARALLEL, 0, 0, 0, l1, l2);
    solve(nm(perp ? "perpendicular" : "parallel", d3));
}

static void t_arc_line_tangent(int other)
{
    start(0);
    Slvs_hEntity c = pt2(0, 0), s = pt2(10, 0), e = pt2(0, 10);
    Slvs_hEntity ar = arc(c, s, e);
    Slvs_hEntity q = pt2(other ? 8 : 12, other ? 11 : 9);
    Slvs_hEntity l = ln(other ? e : s, q);
    fix(c);
    fix(other ? e : s);
    con(other ? SLVS_C_HORIZONTAL : SLVS_C_VERTICAL, 0, c, other ? s : e, 0, 0);
    con(SLVS_C_PT_PT_DISTANCE, 10, other ? e : s, q, 0, 0);
    Slvs_Constraint *k = con(SLVS_C_ARC_LINE_TANGENT, 0, 0, 0, ar, l);
    k->other = other;
    solve(other ? "arc_line_tangent_end" : "arc_line_tangent");
}

static void t_cubic_line_tangent(int d3, int other)
{
    start(d3);
    Slvs_hEntity p0 = pt(0, 0, 0), p1 = pt(3, 5, 1), p2 = pt(7, 5, 2), p3 = pt(10, 0, 0);
    Slvs_hEntity cu = cubic(p0, p1, p2, p3);
    Slvs_hEntity end = other ? p3 : p0;
    Slvs_hEntity q = pt(other ? 14 : -4, 6, 1);
    Slvs_hEntity l = ln(end, q);
    fix(p0);
    fix(p3);
    fix(q);
    if (other) fix(p1); else fix(p2);
    con(SLVS_C_PT_PT_DISTANCE, 5, other ? p3 : p0, other ? p2 : p1, 0, 0);
    Slvs_Constraint *k = con(SLVS_C_CUBIC_LINE_TANGENT, 0, 0, 0, cu, l);
    k->other = other;
    solve(nm(other ? "cubic_line_tangent_end" : "cubic_line_tangent", d3));
}

static void t_equal_radius(int arcs)
{
    start(0);
    Slvs_hEntity c1 = pt2(0, 0), c2 = pt2(20, 0);
    fix(c1);
    fix(c2);
    Slvs_hEntity e1 = circ(c1, 0, 5), e2;
    con(SLVS_C_DIAMETER, 10, 0, 0, e1, 0);
    if (arcs) {
        Slvs_hEntity s = pt2(27, 1), f = pt2(20, 8);
        e2 = arc(c2, s, f);
        con(SLVS_C_HORIZONTAL, 0, c2, s, 0, 0);
        con(SLVS_C_VERTICAL, 0, c2, f, 0, 0);
    } else {
        e2 = circ(c2, 0, 8);
    }
    con(SLVS_C_EQUAL_RADIUS, 0, 0, 0, e1, e2);
    solve(arcs ? "equal_radius_arc" : "equal_radius");
}

static void t_proj_pt_distance(int d3)
{
    start(d3);
    Slvs_hEntity a = pt(0, 0, 0), b = pt(10, 0, 0), p = pt(1, 1, 1), q = pt(7, 4, 2);
    Slvs_hEntity l = ln(a, b);
    fix(a);
    fix(b);
    fix(p);
    con(SLVS_C_PROJ_PT_DISTANCE, 9, p, q, l, 0);
    con(SLVS_C_PT_PT_DISTANCE, 12, p, q, 0, 0);
    solve(nm("proj_pt_distance", d3));
}

static void t_where_dragged(int d3)
{
    start(d3);
    Slvs_hEntity a = pt(1, 2, 3), b = pt(6, 2, 3);
    fix(a);
    con(SLVS_C_PT_PT_DISTANCE, 8, a, b, 0, 0);
    con(SLVS_C_HORIZONTAL + (d3 ? 0 : 0), 0, a, b, 0, 0)->wrkpl = XY;
    solve(nm("where_dragged", d3));
}

static void t_curve_curve_tangent(int kinds, int other, int other2)
{
    /* kinds: 0 arc-arc, 1 arc-cubic, 2 cubic-cubic */
    start(0);
    Slvs_hEntity e1, e2;
    if (kinds < 2) {
        Slvs_hEntity c = pt2(0, 0), s = pt2(10, 0), e = pt2(0, 10);
        fix(c);
        fix(other ? e : s);
        con(other ? SLVS_C_HORIZONTAL : SLVS_C_VERTICAL, 0, c, other ? s : e, 0, 0);
        e1 = arc(c, s, e);
        Slvs_hEntity joint = other ? e : s;
        if (kinds == 0) {
            Slvs_hEntity c2 = pt2(other ? 1 : 19, other ? 19 : 1), s2 = pt2(other ? 1 : 19, other ? 29 : 10);
            Slvs_hEntity ar2 = other2 ? arc(c2, s2, joint) : arc(c2, joint, s2);
            fix(s2);
            e2 = ar2;
        } else {
            Slvs_hEntity p1 = pt2(other ? -4 : 11, other ? 11 : 4), p2 = pt2(15, 12), p3 = pt2(20, 20);
            fix(p2);
            fix(p3);
            e2 = other2 ? cubic(p3, p2, p1, joint) : cubic(joint, p1, p2, p3);
            con(SLVS_C_PT_PT_DISTANCE, 5, joint, p1, 0, 0);
        }
    } else {
        Slvs_hEntity a0 = pt2(0, 0), a1 = pt2(3, 4), a2 = pt2(7, 4), a3 = pt2(10, 0);
        fix(a0);
        fix(a1);
        fix(a2);
        fix(a3);
        e1 = other ? cubic(a0, a1, a2, a3) : cubic(a3, a2, a1, a0);
        Slvs_hEntity b1 = pt2(13, -3), b2 = pt2(17, -3), b3 = pt2(20, 0);
        fix(b2);
        fix(b3);
        e2 = other2 ? cubic(b3, b2, b1, a3) : cubic(a3, b1, b2, b3);
        con(SLVS_C_PT_PT_DISTANCE, 5, a3, b1, 0, 0);
    }
    Slvs_Constraint *k = con(SLVS_C_CURVE_CURVE_TANGENT, 0, 0, 0, e1, e2);
    k->other = other;
    k->other2 = other2;
    static char n[64];
    static const char *kn[] = {"arc_arc", "arc_cubic", "cubic_cubic"};
    snprintf(n, sizeof n, "curve_curve_tangent_%s_%d%d", kn[kinds], other, other2);
    solve(n);
}

static void t_arc_lengths(int type)
{
    start(0);
    Slvs_hEntity c = pt2(0, 0), s = pt2(10, 0), e = pt2(0, 10);
    Slvs_hEntity a1 = arc(c, s, e);
    fix(c);
    fix(s);
    con(SLVS_C_VERTICAL, 0, c, e, 0, 0);
    Slvs_hEntity c2 = pt2(30, 0), s2 = pt2(36, 0), e2 = pt2(30, 7);
    fix(c2);
    fix(s2);
    Slvs_hEntity other;
    double val;
    const char *name;
    if (type == SLVS_C_ARC_ARC_LEN_RATIO || type == SLVS_C_ARC_ARC_DIFFERENCE) {
        other = arc(c2, s2, e2);
        val = type == SLVS_C_ARC_ARC_LEN_RATIO ? 1.5 : 4;
        name = type == SLVS_C_ARC_ARC_LEN_RATIO ? "arc_arc_len_ratio" : "arc_arc_difference";
    } else {
        Slvs_hEntity l0 = pt2(0, -20), l1 = pt2(12, -21);
        fix(l0);
        other = ln(l0, l1);
        con(SLVS_C_HORIZONTAL, 0, 0, 0, other, 0);
        val = type == SLVS_C_ARC_LINE_LEN_RATIO ? 1.25 : 3;
        name = type == SLVS_C_ARC_LINE_LEN_RATIO ? "arc_line_len_ratio" : "arc_line_difference";
    }
    if (type == SLVS_C_ARC_LINE_LEN_RATIO || type == SLVS_C_ARC_LINE_DIFFERENCE)
        con(type, val, 0, 0, other, a1); /* the line first, as libslvs reads it */
    else
        con(type, val, 0, 0, a1, other);
    solve(name);
}

/* ---- behaviour: dragging, failures, groups ---- */

static void t_triangle(void)
{
    start(0);
    Slvs_hEntity a = pt2(0, 0), b = pt2(28, 2), c = pt2(3, 41);
    Slvs_hEntity ab = ln(a, b), ca = ln(c, a);
    fix(a);
    con(SLVS_C_HORIZONTAL, 0, 0, 0, ab, 0);
    con(SLVS_C_PT_PT_DISTANCE, 30, a, b, 0, 0);
    con(SLVS_C_PT_PT_DISTANCE, 40, a, c, 0, 0);
    con(SLVS_C_PT_PT_DISTANCE, 50, b, c, 0, 0);
    (void)ca;
    solve("triangle");
}

static void t_underconstrained(int drag)
{
    start(0);
    Slvs_hEntity a = pt2(10, 20), b = pt2(20, 21);
    con(SLVS_C_PT_PT_DISTANCE, 30, a, b, 0, 0);
    if (drag) {
        S_.dragged[0] = 13;
        S_.dragged[1] = 14;
    }
    solve(drag ? "underconstrained_dragged" : "underconstrained");
}

static void t_drag_unknown_handle(void)
{
    start(0);
    Slvs_hEntity a = pt2(10, 20), b = pt2(20, 21);
    con(SLVS_C_PT_PT_DISTANCE, 30, a, b, 0, 0);
    S_.dragged[0] = 9999;
    solve("dragged_unknown_handle");
}

static void t_drag_one_coordinate(void)
{
    start(0);
    Slvs_hEntity c = pt2(0, 0), p = pt2(7, 9);
    fix(c);
    con(SLVS_C_PT_PT_DISTANCE, 10, c, p, 0, 0);
    S_.dragged[0] = 13;
    solve("dragged_one_coordinate");
}

static void t_empty(void)
{
    start(0);
    pt2(1, 2);
    solve("no_constraints");
}

static void t_inconsistent(int cf)
{
    start(0);
    Slvs_hEntity a = pt2(0, 0), b = pt2(10, 1);
    fix(a);
    con(SLVS_C_PT_PT_DISTANCE, 30, a, b, 0, 0);
    con(SLVS_C_PT_PT_DISTANCE, 40, a, b, 0, 0);
    CF = cf;
    solve(cf ? "inconsistent_distances" : "inconsistent_distances_nofind");
}

static void t_inconsistent_hv(int cf)
{
    start(0);
    Slvs_hEntity a = pt2(0, 0), b = pt2(10, 1);
    Slvs_hEntity l = ln(a, b);
    con(SLVS_C_HORIZONTAL, 0, 0, 0, l, 0);
    con(SLVS_C_VERTICAL, 0, 0, 0, l, 0);
    con(SLVS_C_PT_PT_DISTANCE, 30, a, b, 0, 0);
    CF = cf;
    solve(cf ? "inconsistent_h_v_length" : "inconsistent_h_v_length_nofind");
}

static void t_redundant(int cf)
{
    start(0);
    Slvs_hEntity a = pt2(0, 0), b = pt2(10, 1);
    fix(a);
    con(SLVS_C_PT_PT_DISTANCE, 30, a, b, 0, 0);
    con(SLVS_C_PT_PT_DISTANCE, 30, b, a, 0, 0);
    CF = cf;
    solve(cf ? "redundant_distances" : "redundant_distances_nofind");
}

static void t_redundant_triangle(void)
{
    /* A 3-4-5 triangle with its right angle also given: consistent but one too many. */
    start(0);
    Slvs_hEntity a = pt2(0, 0), b = pt2(29, 1), c = pt2(1, 39);
    Slvs_hEntity ab = ln(a, b), ac = ln(a, c);
    fix(a);
    con(SLVS_C_HORIZONTAL, 0, 0, 0, ab, 0);
    con(SLVS_C_PT_PT_DISTANCE, 30, a, b, 0, 0);
    con(SLVS_C_PT_PT_DISTANCE, 40, a, c, 0, 0);
    con(SLVS_C_PT_PT_DISTANCE, 50, b, c, 0, 0);
    con(SLVS_C_PERPENDICULAR, 0, 0, 0, ab, ac);
    solve("redundant_right_angle");
}

static void t_short_failed_array(void)
{
    start(0);
    Slvs_hEntity a = pt2(0, 0), b = pt2(10, 1);
    fix(a);
    con(SLVS_C_PT_PT_DISTANCE, 30, a, b, 0, 0);
    con(SLVS_C_PT_PT_DISTANCE, 40, a, b, 0, 0);
    con(SLVS_C_PT_PT_DISTANCE, 50, a, b, 0, 0);
    FAILED_ROOM = 1;
    solve("failed_array_of_one");
}

static void t_duplicate_horizontal(void)
{
    start(0);
    Slvs_hEntity a = pt2(0, 0), b = pt2(10, 0);
    Slvs_hEntity l = ln(a, b);
    fix(a);
    con(SLVS_C_HORIZONTAL, 0, 0, 0, l, 0);
    con(SLVS_C_HORIZONTAL, 0, 0, 0, l, 0);
    con(SLVS_C_PT_PT_DISTANCE, 10, a, b, 0, 0);
    solve("duplicate_horizontal");
}

static void t_coincident_cycle(void)
{
    start(0);
    Slvs_hEntity a = pt2(1, 1), b = pt2(1, 1), c = pt2(1, 1);
    fix(a);
    con(SLVS_C_POINTS_COINCIDENT, 0, a, b, 0, 0);
    con(SLVS_C_POINTS_COINCIDENT, 0, b, c, 0, 0);
    con(SLVS_C_POINTS_COINCIDENT, 0, c, a, 0, 0);
    solve("coincident_cycle");
}

static void t_coincident_start_apart(void)
{
    start(0);
    Slvs_hEntity a = pt2(10, 20), b = pt2(20, 21);
    con(SLVS_C_POINTS_COINCIDENT, 0, a, b, 0, 0);
    solve("coincident_points_apart");
}

static void t_groups(void)
{
    /* Group 2: a fixed segment. Group 3: a point 5 away from its end, horizontal from it.
     * Solving group 3 must not move group 2; solving group 1 (nothing to do) moves nothing. */
    start(0);
    Slvs_hEntity a = pt2(0, 0), b = pt2(10, 0);
    fix(a);
    con(SLVS_C_PT_PT_DISTANCE, 12, a, b, 0, 0);
    con(SLVS_C_HORIZONTAL, 0, a, b, 0, 0);
    G = 3;
    Slvs_hEntity p = pt2(14, 2);
    con(SLVS_C_PT_PT_DISTANCE, 5, b, p, 0, 0);
    con(SLVS_C_HORIZONTAL, 0, b, p, 0, 0);
    solve_group("groups_solve_3_first", 3);
    solve_group("groups_solve_2", 2);
    solve_group("groups_solve_1", 1);
    solve_group("groups_solve_absent_9", 9);
}

static void t_tilted_workplane(void)
{
    /* A workplane in group 1 tilted about x, and a rectangle in it. */
    reset();
    G = 1;
    double qw, qx, qy, qz, c = cos(0.5), s = sin(0.5);
    Slvs_MakeQuaternion(1, 0, 0, 0, c, s, &qw, &qx, &qy, &qz);
    Slvs_hEntity o = pt3(1, 2, 3);
    Slvs_hEntity n = nrm3(qw, qx, qy, qz);
    Slvs_hEntity wp = add_entity(Slvs_MakeWorkplane(next_entity++, 1, o, n));
    G = 2;
    W = wp;
    Slvs_hEntity a = pt2(0, 0), b = pt2(9, 1), cc = pt2(10, 6), d = pt2(1, 5);
    Slvs_hEntity ab = ln(a, b), bc = ln(b, cc), cd = ln(cc, d), da = ln(d, a);
    fix(a);
    con(SLVS_C_HORIZONTAL, 0, 0, 0, ab, 0);
    con(SLVS_C_VERTICAL, 0, 0, 0, bc, 0);
    con(SLVS_C_HORIZONTAL, 0, 0, 0, cd, 0);
    con(SLVS_C_VERTICAL, 0, 0, 0, da, 0);
    con(SLVS_C_PT_PT_DISTANCE, 12, a, b, 0, 0);
    con(SLVS_C_PT_PT_DISTANCE, 7, b, cc, 0, 0);
    /* A 3D point 4 above the plane's corner c. */
    W = 0;
    Slvs_hEntity up = pt3(5, 5, 5);
    con(SLVS_C_PT_PLANE_DISTANCE, 3, up, 0, wp, 0);
    con(SLVS_C_PT_PT_DISTANCE, 4, up, cc, 0, 0);
    solve("tilted_workplane_rectangle");
}

static void t_3d_normal_in_group(void)
{
    /* A workplane whose normal is unknown (group 2), aligned to the xy plane's normal. */
    reset();
    W = 0;
    Slvs_hEntity o = pt3(0, 0, 1);
    fix(o);
    Slvs_hEntity n = nrm3(0.95, 0.1, 0.2, 0.05);
    con(SLVS_C_SAME_ORIENTATION, 0, 0, 0, n, 102);
    Slvs_hEntity wp = add_entity(Slvs_MakeWorkplane(next_entity++, 2, o, n));
    W = wp;
    Slvs_hEntity p = pt2(3, 4);
    fix(p);
    solve("free_normal_workplane");
}

static void t_arc_all_points_fixed(void)
{
    /* Centre, start and end all fixed: the arc's own equal-radius condition is redundant. */
    start(0);
    Slvs_hEntity c = pt2(0, 0), s = pt2(10, 0), e = pt2(0, 10);
    arc(c, s, e);
    fix(c);
    fix(s);
    fix(e);
    solve("arc_all_points_fixed");
}

static void t_three_conflicting(void)
{
    start(0);
    Slvs_hEntity a = pt2(0, 0), b = pt2(10, 1);
    fix(a);
    con(SLVS_C_PT_PT_DISTANCE, 30, a, b, 0, 0);
    con(SLVS_C_PT_PT_DISTANCE, 40, a, b, 0, 0);
    con(SLVS_C_PT_PT_DISTANCE, 50, a, b, 0, 0);
    solve("three_conflicting_distances");
}

static void t_proj_on_normal(void)
{
    start(1);
    Slvs_hEntity p = pt3(1, 1, 1), q = pt3(7, 4, 2);
    fix(p);
    con(SLVS_C_PROJ_PT_DISTANCE, 9, p, q, 102, 0);
    con(SLVS_C_PT_PT_DISTANCE, 12, p, q, 0, 0);
    solve("proj_pt_distance_normal");
}

static void t_chain(int n)
{
    /* A chain of n segments in the plane: joints coincident, lengths and neighbour angles
     * fixed, the first point fixed, everything else started a little off. */
    start(0);
    Slvs_hEntity prev_end = 0, prev_line = 0, first = 0;
    double x = 0, y = 0;
    for (int i = 0; i < n; i++) {
        double ang = 0.3 * sin(i);
        Slvs_hEntity a = pt2(x + 0.1 * (i % 3), y - 0.1 * (i % 2));
        x += 10 * cos(ang);
        y += 10 * sin(ang);
        Slvs_hEntity b = pt2(x + 0.2, y - 0.1);
        Slvs_hEntity l = ln(a, b);
        if (i == 0) {
            first = a;
            con(SLVS_C_HORIZONTAL, 0, 0, 0, l, 0);
        } else {
            con(SLVS_C_POINTS_COINCIDENT, 0, prev_end, a, 0, 0);
            con(SLVS_C_ANGLE, 20, 0, 0, prev_line, l);
        }
        con(SLVS_C_PT_PT_DISTANCE, 10, a, b, 0, 0);
        prev_end = b;
        prev_line = l;
    }
    fix(first);
    static char nme[32];
    snprintf(nme, sizeof nme, "chain_%d", n);
    solve(nme);
}

static void t_quaternions(void)
{
    static const double uv[][6] = {
        {1, 0, 0, 0, 1, 0},
        {0, 1, 0, 0, 0, 1},
        {0, 0, 1, 1, 0, 0},
        {-1, 0, 0, 0, 1, 0},
        {1, 0, 0, 0, -1, 0},
        {0.6, 0.8, 0, -0.8, 0.6, 0},
        {0, 0, -1, 0, 1, 0},
    };
    for (unsigned i = 0; i < sizeof uv / sizeof uv[0]; i++) {
        double q[4], u[3], v[3], n[3];
        Slvs_MakeQuaternion(uv[i][0], uv[i][1], uv[i][2], uv[i][3], uv[i][4], uv[i][5],
                            &q[0], &q[1], &q[2], &q[3]);
        Slvs_QuaternionU(q[0], q[1], q[2], q[3], &u[0], &u[1], &u[2]);
        Slvs_QuaternionV(q[0], q[1], q[2], q[3], &v[0], &v[1], &v[2]);
        Slvs_QuaternionN(0.5, 0.5, -0.5, 0.5, &n[0], &n[1], &n[2]);
        printf("quaternion_%u|0|0|0||", i);
        for (int k = 0; k < 4; k++) printf("%d=%.12g,", k + 1, q[k]);
        for (int k = 0; k < 3; k++) printf("%d=%.12g,", k + 11, u[k]);
        for (int k = 0; k < 3; k++) printf("%d=%.12g,", k + 21, v[k]);
        for (int k = 0; k < 3; k++) printf("%d=%.12g,", k + 31, n[k]);
        printf("\n");
    }
}

int main(void)
{
    for (int d3 = 0; d3 < 2; d3++) {
        t_points_coincident(d3);
        t_pt_pt_distance(d3);
        t_pt_line_distance(d3);
        t_pt_on_line(d3);
        t_equal_length_lines(d3);
        t_length_ratio(d3);
        t_length_difference(d3);
        t_eq_len_pt_line_d(d3);
        t_eq_pt_ln_distances(d3);
        t_equal_angle(d3, 0);
        t_equal_angle(d3, 1);
        t_symmetric(d3);
        t_at_midpoint(d3);
        t_angle(d3, 0);
        t_angle(d3, 1);
        t_parallel_perpendicular(d3, 0);
        t_parallel_perpendicular(d3, 1);
        t_cubic_line_tangent(d3, 0);
        t_cubic_line_tangent(d3, 1);
        t_proj_pt_distance(d3);
        t_where_dragged(d3);
    }
    t_pt_plane_distance();
    t_pt_face_distance();
    t_pt_in_plane();
    t_pt_on_face();
    t_equal_line_arc_len();
    t_symmetric_hv(0);
    t_symmetric_hv(1);
    t_symmetric_line();
    for (int v = 0; v < 2; v++)
        for (int p = 0; p < 2; p++) t_horizontal_vertical(v, p);
    for (int i = 0; i < 3; i++) t_diameter(i);
    t_pt_on_circle(0);
    t_pt_on_circle(1);
    t_same_orientation();
    t_arc_line_tangent(0);
    t_arc_line_tangent(1);
    t_equal_radius(0);
    t_equal_radius(1);
    for (int k = 0; k < 3; k++)
        for (int o = 0; o < 2; o++)
            for (int o2 = 0; o2 < 2; o2++) t_curve_curve_tangent(k, o, o2);
    t_arc_lengths(SLVS_C_ARC_ARC_LEN_RATIO);
    t_arc_lengths(SLVS_C_ARC_LINE_LEN_RATIO);
    t_arc_lengths(SLVS_C_ARC_ARC_DIFFERENCE);
    t_arc_lengths(SLVS_C_ARC_LINE_DIFFERENCE);

    t_triangle();
    t_underconstrained(0);
    t_underconstrained(1);
    t_drag_unknown_handle();
    t_drag_one_coordinate();
    t_empty();
    t_inconsistent(1);
    t_inconsistent(0);
    t_inconsistent_hv(1);
    t_inconsistent_hv(0);
    t_redundant(1);
    t_redundant(0);
    t_redundant_triangle();
    t_short_failed_array();
    t_duplicate_horizontal();
    t_coincident_cycle();
    t_coincident_start_apart();
    t_groups();
    t_tilted_workplane();
    t_3d_normal_in_group();
    t_arc_all_points_fixed();
    t_three_conflicting();
    t_proj_on_normal();
    t_chain(12);
    t_quaternions();
    return 0;
}
