/* Runs one benchmark problem through SolveSpace's C library (libslvs).
 *
 * usage: slvs_runner PROBLEM.txt REPS BUDGET_S OUT.json
 *
 * PROBLEM.txt holds libslvs records (see loci-bench's slvs::to_records). Each repetition
 * copies the records into fresh Slvs arrays (timed as the build) and calls Slvs_Solve
 * (timed as the solve); repetitions stop early once the solves add up to BUDGET_S seconds.
 * OUT.json receives {status, detail, build_ms, solve_ms, points}. */
#include <slvs.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now_ms(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

#define GROW(arr, n, cap)                                                   \
    do {                                                                    \
        if ((n) == (cap)) {                                                 \
            (cap) = (cap) ? 2 * (cap) : 1024;                               \
            (arr) = realloc((arr), (size_t)(cap) * sizeof(*(arr)));         \
            if (!(arr)) { fprintf(stderr, "out of memory\n"); exit(4); }    \
        }                                                                   \
    } while (0)

int main(int argc, char **argv) {
    if (argc != 5) {
        fprintf(stderr, "usage: slvs_runner PROBLEM.txt REPS BUDGET_S OUT.json\n");
        return 3;
    }
    FILE *in = fopen(argv[1], "r");
    if (!in) { perror(argv[1]); return 3; }
    int reps = atoi(argv[2]);
    double budget_ms = atof(argv[3]) * 1e3;

    Slvs_Param *P = NULL; int np = 0, capp = 0;
    Slvs_Entity *E = NULL; int ne = 0, cape = 0;
    Slvs_Constraint *C = NULL; int nc = 0, capc = 0;
    Slvs_hEntity *out = NULL; int no = 0, capo = 0;
    unsigned group = 2;
    char tag[4];
    while (fscanf(in, "%3s", tag) == 1) {
        if (tag[0] == 'G') {
            if (fscanf(in, "%u", &group) != 1) return 3;
        } else if (tag[0] == 'P') {
            GROW(P, np, capp);
            Slvs_Param *p = &P[np++];
            if (fscanf(in, "%u %u %lf", &p->h, &p->group, &p->val) != 3) return 3;
        } else if (tag[0] == 'E') {
            GROW(E, ne, cape);
            Slvs_Entity *e = &E[ne++];
            memset(e, 0, sizeof *e);
            if (fscanf(in, "%u %u %d %u %u %u %u %u %u %u %u %u %u %u", &e->h, &e->group, &e->type,
                       &e->wrkpl, &e->point[0], &e->point[1], &e->point[2], &e->point[3], &e->normal,
                       &e->distance, &e->param[0], &e->param[1], &e->param[2], &e->param[3]) != 14)
                return 3;
        } else if (tag[0] == 'C') {
            GROW(C, nc, capc);
            Slvs_Constraint *c = &C[nc++];
            memset(c, 0, sizeof *c);
            if (fscanf(in, "%u %u %d %u %lf %u %u %u %u %u %u %d %d", &c->h, &c->group, &c->type,
                       &c->wrkpl, &c->valA, &c->ptA, &c->ptB, &c->entityA, &c->entityB, &c->entityC,
                       &c->entityD, &c->other, &c->other2) != 13)
                return 3;
        } else if (tag[0] == 'O') {
            unsigned h;
            while (fscanf(in, "%u", &h) == 1) {
                GROW(out, no, capo);
                out[no++] = h;
            }
        } else {
            fprintf(stderr, "unknown record %s\n", tag);
            return 3;
        }
    }
    fclose(in);

    Slvs_System sys;
    Slvs_Param *work = malloc((size_t)(np ? np : 1) * sizeof *work);
    Slvs_hConstraint *failed = malloc((size_t)(nc ? nc : 1) * sizeof *failed);
    double *build = malloc((size_t)(reps > 0 ? reps : 1) * sizeof(double));
    double *solve = malloc((size_t)(reps > 0 ? reps : 1) * sizeof(double));
    int done = 0, result = 0;
    double spent = 0;
    for (int r = 0; r < reps; r++) {
        double t0 = now_ms();
        memcpy(work, P, (size_t)np * sizeof *work);
        memset(&sys, 0, sizeof sys);
        sys.param = work; sys.params = np;
        sys.entity = E; sys.entities = ne;
        sys.constraint = C; sys.constraints = nc;
        sys.failed = failed; sys.faileds = nc;
        sys.calculateFaileds = 1;
        double t1 = now_ms();
        Slvs_Solve(&sys, group);
        double t2 = now_ms();
        build[done] = t1 - t0;
        solve[done] = t2 - t1;
        done++;
        result = sys.result;
        spent += t2 - t1;
        if (spent > budget_ms) break;
    }

    FILE *o = fopen(argv[4], "w");
    if (!o) { perror(argv[4]); return 3; }
    const char *status = "ok", *detail = "okay";
    switch (result) {
    case SLVS_RESULT_OKAY: break;
    case SLVS_RESULT_INCONSISTENT: status = "failed"; detail = "inconsistent"; break;
    case SLVS_RESULT_DIDNT_CONVERGE: status = "failed"; detail = "did not converge"; break;
    case SLVS_RESULT_TOO_MANY_UNKNOWNS: status = "refused"; detail = "too many unknowns"; break;
    default: status = "failed"; detail = "unknown result"; break;
    }
    fprintf(o, "{\"status\":\"%s\",\"detail\":\"%s (dof %d, %d failed)\",\"build_ms\":[", status, detail,
            sys.dof, sys.faileds);
    for (int i = 0; i < done; i++) fprintf(o, "%s%.6f", i ? "," : "", build[i]);
    fprintf(o, "],\"solve_ms\":[");
    for (int i = 0; i < done; i++) fprintf(o, "%s%.6f", i ? "," : "", solve[i]);
    fprintf(o, "],\"points\":[");
    /* Handle -> index tables, so reading back is linear in the problem size. */
    unsigned maxp = 0, maxe = 0;
    for (int q = 0; q < np; q++) if (P[q].h > maxp) maxp = P[q].h;
    for (int k = 0; k < ne; k++) if (E[k].h > maxe) maxe = E[k].h;
    int *pix = calloc((size_t)maxp + 1, sizeof(int));
    int *eix = calloc((size_t)maxe + 1, sizeof(int));
    if (!pix || !eix) { fprintf(stderr, "out of memory\n"); return 4; }
    for (int q = 0; q < np; q++) pix[P[q].h] = q + 1;
    for (int k = 0; k < ne; k++) eix[E[k].h] = k + 1;
    for (int i = 0; i < no; i++) {
        double xyz[3] = {0, 0, 0};
        int k = out[i] <= maxe ? eix[out[i]] - 1 : -1;
        if (k >= 0) {
            int n = E[k].type == SLVS_E_POINT_IN_3D ? 3 : 2;
            for (int j = 0; j < n; j++) {
                unsigned ph = E[k].param[j];
                int q = ph <= maxp ? pix[ph] - 1 : -1;
                if (q >= 0) xyz[j] = work[q].val;
            }
        }
        fprintf(o, "%s[%.17g,%.17g,%.17g]", i ? "," : "", xyz[0], xyz[1], xyz[2]);
    }
    fprintf(o, "]}\n");
    fclose(o);
    return 0;
}
