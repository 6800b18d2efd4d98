/* Prints the size and field offsets of every slvs.h struct and the value of every constant,
 * so that loci's header can be compared with libslvs's. */
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <slvs.h>

#define SZ(t) printf("sizeof %s %zu\n", #t, sizeof(t))
#define OFF(t, f) printf("offset %s.%s %zu\n", #t, #f, offsetof(t, f))
#define K(c) printf("const %s %ld\n", #c, (long)(c))

int main(void)
{
    SZ(Slvs_hParam); SZ(Slvs_hEntity); SZ(Slvs_hConstraint); SZ(Slvs_hGroup);
    SZ(Slvs_Param); OFF(Slvs_Param, h); OFF(Slvs_Param, group); OFF(Slvs_Param, val);
    SZ(Slvs_Entity); OFF(Slvs_Entity, h); OFF(Slvs_Entity, group); OFF(Slvs_Entity, type);
    OFF(Slvs_Entity, wrkpl); OFF(Slvs_Entity, point); OFF(Slvs_Entity, normal);
    OFF(Slvs_Entity, distance); OFF(Slvs_Entity, param);
    SZ(Slvs_Constraint); OFF(Slvs_Constraint, h); OFF(Slvs_Constraint, group);
    OFF(Slvs_Constraint, type); OFF(Slvs_Constraint, wrkpl); OFF(Slvs_Constraint, valA);
    OFF(Slvs_Constraint, ptA); OFF(Slvs_Constraint, ptB); OFF(Slvs_Constraint, entityA);
    OFF(Slvs_Constraint, entityB); OFF(Slvs_Constraint, entityC); OFF(Slvs_Constraint, entityD);
    OFF(Slvs_Constraint, other); OFF(Slvs_Constraint, other2);
    SZ(Slvs_System); OFF(Slvs_System, param); OFF(Slvs_System, params); OFF(Slvs_System, entity);
    OFF(Slvs_System, entities); OFF(Slvs_System, constraint); OFF(Slvs_System, constraints);
    OFF(Slvs_System, dragged); OFF(Slvs_System, calculateFaileds); OFF(Slvs_System, failed);
    OFF(Slvs_System, faileds); OFF(Slvs_System, dof); OFF(Slvs_System, result);
    K(SLVS_FREE_IN_3D);
    K(SLVS_E_POINT_IN_3D); K(SLVS_E_POINT_IN_2D); K(SLVS_E_NORMAL_IN_3D); K(SLVS_E_NORMAL_IN_2D);
    K(SLVS_E_DISTANCE); K(SLVS_E_WORKPLANE); K(SLVS_E_LINE_SEGMENT); K(SLVS_E_CUBIC);
    K(SLVS_E_CIRCLE); K(SLVS_E_ARC_OF_CIRCLE);
    K(SLVS_C_POINTS_COINCIDENT); K(SLVS_C_PT_PT_DISTANCE); K(SLVS_C_PT_PLANE_DISTANCE);
    K(SLVS_C_PT_LINE_DISTANCE); K(SLVS_C_PT_FACE_DISTANCE); K(SLVS_C_PT_IN_PLANE);
    K(SLVS_C_PT_ON_LINE); K(SLVS_C_PT_ON_FACE); K(SLVS_C_EQUAL_LENGTH_LINES);
    K(SLVS_C_LENGTH_RATIO); K(SLVS_C_EQ_LEN_PT_LINE_D); K(SLVS_C_EQ_PT_LN_DISTANCES);
    K(SLVS_C_EQUAL_ANGLE); K(SLVS_C_EQUAL_LINE_ARC_LEN); K(SLVS_C_SYMMETRIC);
    K(SLVS_C_SYMMETRIC_HORIZ); K(SLVS_C_SYMMETRIC_VERT); K(SLVS_C_SYMMETRIC_LINE);
    K(SLVS_C_AT_MIDPOINT); K(SLVS_C_HORIZONTAL); K(SLVS_C_VERTICAL); K(SLVS_C_DIAMETER);
    K(SLVS_C_PT_ON_CIRCLE); K(SLVS_C_SAME_ORIENTATION); K(SLVS_C_ANGLE); K(SLVS_C_PARALLEL);
    K(SLVS_C_PERPENDICULAR); K(SLVS_C_ARC_LINE_TANGENT); K(SLVS_C_CUBIC_LINE_TANGENT);
    K(SLVS_C_EQUAL_RADIUS); K(SLVS_C_PROJ_PT_DISTANCE); K(SLVS_C_WHERE_DRAGGED);
    K(SLVS_C_CURVE_CURVE_TANGENT); K(SLVS_C_LENGTH_DIFFERENCE); K(SLVS_C_ARC_ARC_LEN_RATIO);
    K(SLVS_C_ARC_LINE_LEN_RATIO); K(SLVS_C_ARC_ARC_DIFFERENCE); K(SLVS_C_ARC_LINE_DIFFERENCE);
    K(SLVS_RESULT_OKAY); K(SLVS_RESULT_INCONSISTENT); K(SLVS_RESULT_DIDNT_CONVERGE);
    K(SLVS_RESULT_TOO_MANY_UNKNOWNS);
    /* The inline constructors fill the same fields. */
    Slvs_Entity e = Slvs_MakeArcOfCircle(1, 2, 3, 4, 5, 6, 7);
    Slvs_Constraint c = Slvs_MakeConstraint(1, 2, 3, 4, 5.5, 6, 7, 8, 9);
    printf("arc %u %u %d %u %u %u %u %u %u %u\n", e.h, e.group, e.type, e.wrkpl, e.normal,
           e.point[0], e.point[1], e.point[2], e.point[3], e.param[0]);
    printf("con %u %u %d %u %g %u %u %u %u %u %u %d %d\n", c.h, c.group, c.type, c.wrkpl, c.valA,
           c.ptA, c.ptB, c.entityA, c.entityB, c.entityC, c.entityD, c.other, c.other2);
    return 0;
}
