/* The collide-first stepping rule (docs/stepping-rules.md, section 5) as an outside solver in
 * plain C99: the reference client of the protocol in docs/your-solver.md. It needs no collide
 * header and no library beyond libm:
 *
 *     cc -O2 -ffp-contract=off -o c_stepper c_stepper.c -lm
 *     collide validate SUITE --solver c=./c_stepper --solver-rule c=collide-first
 *
 * collide runs `./c_stepper REQUEST_DIR`; the program reads REQUEST_DIR/request.txt and
 * initial.npy and writes states.npy and result.txt there. It adds each disk's contacts in the
 * order of the other disks' numbers, as numpy_stepper.py does, so the two agree to rounding.
 * Pairs are found by testing all of them (N^2 per step): a reference, not a fast code. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    double dt, start, xmin, ymin, xmax, ymax, e, e_wall, mu, gx, gy, gamma;
    int periodic, collide_first;
    long disks, n_times;
    double *times;
} Request;

static void die(const char *what, const char *detail) {
    fprintf(stderr, "c_stepper: %s%s\n", what, detail ? detail : "");
    exit(1);
}

static FILE *open_in(const char *dir, const char *name, const char *mode) {
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, mode);
    if (!f) die("cannot open ", path);
    return f;
}

/* request.txt: "key value" lines; output_times holds a list. */
static Request read_request(const char *dir) {
    Request q;
    memset(&q, 0, sizeof q);
    FILE *f = open_in(dir, "request.txt", "r");
    static char line[1 << 20];
    while (fgets(line, sizeof line, f)) {
        char key[64], word[64];
        double v = 0;
        if (sscanf(line, "%63s", key) != 1) continue;
        const char *rest = line + strlen(key);
        if (strcmp(key, "output_times") == 0) {
            char *p = (char *)rest, *end;
            q.times = malloc(sizeof(double) * (strlen(rest) / 2 + 1));
            for (double t = strtod(p, &end); end != p; t = strtod(p, &end)) { q.times[q.n_times++] = t; p = end; }
        } else if (strcmp(key, "boundary") == 0 && sscanf(rest, "%63s", word) == 1) {
            q.periodic = strcmp(word, "periodic") == 0;
        } else if (strcmp(key, "order") == 0 && sscanf(rest, "%63s", word) == 1) {
            q.collide_first = strcmp(word, "collide-first") == 0;
        } else if (sscanf(rest, "%lf", &v) == 1) {
            if (!strcmp(key, "dt")) q.dt = v;
            else if (!strcmp(key, "start_time")) q.start = v;
            else if (!strcmp(key, "disks")) q.disks = (long)v;
            else if (!strcmp(key, "xmin")) q.xmin = v;
            else if (!strcmp(key, "ymin")) q.ymin = v;
            else if (!strcmp(key, "xmax")) q.xmax = v;
            else if (!strcmp(key, "ymax")) q.ymax = v;
            else if (!strcmp(key, "restitution")) q.e = v;
            else if (!strcmp(key, "wall_restitution")) q.e_wall = v;
            else if (!strcmp(key, "friction")) q.mu = v;
            else if (!strcmp(key, "gravity_x")) q.gx = v;
            else if (!strcmp(key, "gravity_y")) q.gy = v;
            else if (!strcmp(key, "damping")) q.gamma = v;
        }
    }
    fclose(f);
    return q;
}

/* initial.npy: a version 1 header (10 bytes + its length), then (N, 7) little-endian float64:
 * x, y, vx, vy, radius, mass, stone. */
static double *read_initial(const char *dir, long n) {
    FILE *f = open_in(dir, "initial.npy", "rb");
    unsigned char head[10];
    if (fread(head, 1, 10, f) != 10 || memcmp(head, "\x93NUMPY\x01", 7) != 0) die("initial.npy: not a version 1 .npy file", 0);
    fseek(f, 10 + head[8] + 256L * head[9], SEEK_SET);
    double *table = malloc(sizeof(double) * 7 * (size_t)n);
    if ((long)fread(table, sizeof(double), 7 * (size_t)n, f) != 7 * n) die("initial.npy: too short", 0);
    fclose(f);
    return table;
}

/* states.npy: (K, N, 4) float64, the header padded to 64 bytes as the format asks. */
static void write_states(const char *dir, const double *states, long k, long n) {
    char header[128];
    int len = snprintf(header, sizeof header, "{'descr': '<f8', 'fortran_order': False, 'shape': (%ld, %ld, 4), }", k, n);
    while ((10 + len + 1) % 64) header[len++] = ' ';
    header[len++] = '\n';
    FILE *f = open_in(dir, "states.npy", "wb");
    fwrite("\x93NUMPY\x01\x00", 1, 8, f);
    fputc(len & 0xff, f);
    fputc(len >> 8, f);
    fwrite(header, 1, (size_t)len, f);
    fwrite(states, sizeof(double), (size_t)(k * n * 4), f);
    fclose(f);
}

/* The wall law (physics/wall_law.cl.h): clamp and reflect, or wrap into [lo, lo + length). */
static void reflect(double *x, double *v, double r, double lo, double hi, double e) {
    if (*x - r < lo) { *x = lo + r; if (*v < 0) *v = -e * *v; }
    else if (*x + r > hi) { *x = hi - r; if (*v > 0) *v = -e * *v; }
}
static double wrap(double x, double lo, double length) {
    double r = x - lo;
    r -= length * floor(r / length);
    if (r >= length) r -= length;
    return lo + r;
}

int main(int argc, char **argv) {
    if (argc != 2) die("usage: c_stepper REQUEST_DIR", 0);
    const char *dir = argv[1];
    Request q = read_request(dir);
    if (!q.collide_first) {
        FILE *f = open_in(dir, "result.txt", "w");
        fprintf(f, "refuse only the collide-first order\n");
        fclose(f);
        free(q.times);
        return 0;
    }
    const long n = q.disks;
    double *s = read_initial(dir, n), *w = malloc(sizeof(double) * n), *d = calloc(4 * (size_t)n, sizeof(double));
    double *out = malloc(sizeof(double) * 4 * (size_t)(n * q.n_times));
    for (long i = 0; i < n; ++i) w[i] = s[7 * i + 6] != 0 ? 0.0 : 1.0 / s[7 * i + 5];
    const double lx = q.xmax - q.xmin, ly = q.ymax - q.ymin;
    long step = lround(q.start / q.dt), steps = 0, contacts = 0;
    for (long k = 0; k < q.n_times; ++k) {
        for (; step < lround(q.times[k] / q.dt); ++step, ++steps) {
            for (long i = 0; i < n; ++i) {           /* contact shares from one snapshot */
                double *di = d + 4 * i, *a = s + 7 * i;
                di[0] = di[1] = di[2] = di[3] = 0;
                if (w[i] == 0) continue;
                for (long j = 0; j < n; ++j) {
                    const double *b = s + 7 * j;
                    double sx = a[0] - b[0], sy = a[1] - b[1];
                    if (j == i) continue;
                    if (q.periodic) { sx -= lx * rint(sx / lx); sy -= ly * rint(sy / ly); }
                    const double reach = a[4] + b[4], dist2 = sx * sx + sy * sy, wsum = w[i] + w[j];
                    if (dist2 >= reach * reach || dist2 == 0 || wsum == 0) continue;
                    if (i < j || w[j] == 0) ++contacts;
                    const double dist = sqrt(dist2), nx = sx / dist, ny = sy / dist;
                    const double share = w[i] / wsum * (reach - dist);
                    di[0] += share * nx;
                    di[1] += share * ny;
                    const double ux = a[2] - b[2], uy = a[3] - b[3], un = ux * nx + uy * ny;
                    const double jn = un < 0 ? -(1 + q.e) * un / wsum : 0.0;
                    double dvx = w[i] * jn * nx, dvy = w[i] * jn * ny;
                    if (q.mu > 0) {
                        const double tx = ux - un * nx, ty = uy - un * ny, speed = sqrt(tx * tx + ty * ty);
                        if (speed > 0) {
                            const double jt = fmin(q.mu * jn, speed / wsum);
                            dvx -= w[i] * (jt / speed) * tx;
                            dvy -= w[i] * (jt / speed) * ty;
                        }
                    }
                    di[2] += dvx;
                    di[3] += dvy;
                }
            }
            for (long i = 0; i < n; ++i) {
                double *a = s + 7 * i;
                for (int c = 0; c < 4; ++c) a[c] += d[4 * i + c];
                if (w[i] == 0) continue;                 /* stones never move */
                a[0] += a[2] * q.dt;
                a[1] += a[3] * q.dt;
                a[2] += (q.gx - q.gamma * a[2]) * q.dt;
                a[3] += (q.gy - q.gamma * a[3]) * q.dt;
                if (q.periodic) { a[0] = wrap(a[0], q.xmin, lx); a[1] = wrap(a[1], q.ymin, ly); }
                else { reflect(&a[0], &a[2], a[4], q.xmin, q.xmax, q.e_wall); reflect(&a[1], &a[3], a[4], q.ymin, q.ymax, q.e_wall); }
            }
        }
        for (long i = 0; i < n; ++i) memcpy(out + 4 * (k * n + i), s + 7 * i, 4 * sizeof(double));
    }
    write_states(dir, out, q.n_times, n);
    FILE *f = open_in(dir, "result.txt", "w");
    fprintf(f, "times");
    for (long k = 0; k < q.n_times; ++k) fprintf(f, " %.17g", q.times[k]);
    fprintf(f, "\nsteps %ld\ncontacts %ld\nversion c-stepper 1\n", steps, contacts);
    fclose(f);
    free(out), free(d), free(w), free(s), free(q.times);
    return 0;
}
