/* The float64 reduction map as a plain C loop: the yardstick of bench_numerics.py.
 *
 * The same step as certify/numerics/kernel.py (rules.classify, rules.advance, the
 * rounding bound of the step, the accumulated error bound rules.carry_bound with the
 * certified horizon, and the power-of-2 rescaling), one orbit, no storage.  Reads
 * from stdin (as printed by bench_numerics.py, floats in hex "%a" form):
 *     collisions repeat tol g K tiny i0 n0[3] rows[27]
 * rows[j*9 + m*3 + c] = cof(K_j)[m][c] as floats.
 * Prints: code done certified checksum seconds_per_run (best of `repeat` runs).
 *
 *     cc -O2 -o loop benchmarks/loop.c -lm
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);   /* CPU time: per core, robust to a loaded machine */
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static const double BIG = 0x1p256, SMALL = 0x1p-256;

static int certifies(int i, const double *n, const double *e, int nx) {
    int a = (i + 1) % 3, b = (i + 2) % 3;
    if (!(n[a] > e[a] && n[b] < -e[b])) return 0;
    return nx == a ? n[i] > e[i] : n[i] < -e[i];
}

static int run(long collisions, double tol, double g, double K, double tiny, int i0, const double *n0,
               const double *rows, long *done, long *cert, long *check) {
    double n[3] = {n0[0], n0[1], n0[2]}, b[3], e[3];
    double top = fmax(fabs(n[0]), fmax(fabs(n[1]), fabs(n[2])));
    b[0] = b[1] = b[2] = e[0] = e[1] = e[2] = tol * top;
    int i = i0;
    long h = 0, certified = -1;
    for (long c = 0; c < collisions; c++) {
        int j = (i + 1) % 3, k = (i + 2) % 3, nx, code = 0;
        if (!isfinite(n[0]) || !isfinite(n[1]) || !isfinite(n[2])) code = 4;
        else if (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0) code = 3;
        else if (n[j] < -b[j] || n[k] > b[k]) code = 3;
        else if (n[j] <= b[j] || n[k] >= -b[k]) code = 2;
        else if (n[i] > b[i]) nx = j;
        else if (n[i] < -b[i]) nx = k;
        else code = 1;
        if (code) { *done = c; *cert = certified < 0 ? c : certified; *check = h; return code; }
        if (certified < 0 && !certifies(i, n, e, nx)) certified = c;
        const double *R = rows + 9 * nx;
        double a0 = fabs(n[0]), a1 = fabs(n[1]), a2 = fabs(n[2]);
        double m0 = R[0] * n[0] + R[1] * n[1] + R[2] * n[2];
        double m1 = R[3] * n[0] + R[4] * n[1] + R[5] * n[2];
        double m2 = R[6] * n[0] + R[7] * n[1] + R[8] * n[2];
        int t = (nx + 1) % 3;
        double mt = t == 0 ? m0 : (t == 1 ? m1 : m2);
        if (mt < 0.0) { m0 = -m0; m1 = -m1; m2 = -m2; }
        b[0] = tol * (fabs(R[0]) * a0 + fabs(R[1]) * a1 + fabs(R[2]) * a2);
        b[1] = tol * (fabs(R[3]) * a0 + fabs(R[4]) * a1 + fabs(R[5]) * a2);
        b[2] = tol * (fabs(R[6]) * a0 + fabs(R[7]) * a1 + fabs(R[8]) * a2);
        double t0 = e[0] + g * a0, t1 = e[1] + g * a1, t2 = e[2] + g * a2;
        e[0] = (fabs(R[0]) * t0 + fabs(R[1]) * t1 + fabs(R[2]) * t2) * K + tiny;
        e[1] = (fabs(R[3]) * t0 + fabs(R[4]) * t1 + fabs(R[5]) * t2) * K + tiny;
        e[2] = (fabs(R[6]) * t0 + fabs(R[7]) * t1 + fabs(R[8]) * t2) * K + tiny;
        double nt = fmax(fabs(m0), fmax(fabs(m1), fabs(m2)));
        if (nt > BIG || (nt < SMALL && nt > 0.0)) {
            int ex;
            frexp(nt, &ex);
            double f = ldexp(1.0, -ex);
            m0 *= f; m1 *= f; m2 *= f; b[0] *= f; b[1] *= f; b[2] *= f;
            e[0] = e[0] * f + tiny; e[1] = e[1] * f + tiny; e[2] = e[2] * f + tiny;
        }
        n[0] = m0; n[1] = m1; n[2] = m2;
        i = nx;
        h = (h * 3 + nx) & 0xFFFFFFFFFFFFL;   /* the word in base 3, mod 2^48 */
    }
    *done = collisions;
    *cert = certified < 0 ? collisions : certified;
    *check = h;
    return 0;
}

int main(void) {
    long collisions, repeat;
    double tol, g, K, tiny, n0[3], rows[27];
    int i0;
    if (scanf("%ld %ld %lf %lf %lf %lf %d", &collisions, &repeat, &tol, &g, &K, &tiny, &i0) != 7) return 2;
    for (int a = 0; a < 3; a++) if (scanf("%lf", &n0[a]) != 1) return 2;
    for (int a = 0; a < 27; a++) if (scanf("%lf", &rows[a]) != 1) return 2;
    long done = 0, cert = 0, check = 0;
    int code = 0;
    double best = 1e300;
    for (long k = 0; k < repeat; k++) {
        double t0 = now();
        code = run(collisions, tol, g, K, tiny, i0, n0, rows, &done, &cert, &check);
        double dt = now() - t0;
        if (dt < best) best = dt;
    }
    printf("%d %ld %ld %ld %.9g\n", code, done, cert, check, best);
    return 0;
}
