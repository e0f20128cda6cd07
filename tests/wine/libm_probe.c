/* The math library calls of the FMU binary, on fixed pseudo-random arguments:
 * compiled for Linux (glibc's libm) and for Windows (MinGW-w64: msvcrt.dll's
 * functions and libmingwex's sincos, the same the win64 DLL imports or links),
 * so that the Wine test can show how far the two libraries' results differ, the
 * source of the last-bit differences between the two binaries' outputs.
 *
 * stdout: one line per function, "NAME bits bits ..." (hexadecimal IEEE bits).
 * Build without builtins so that every call reaches the library. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

void sincos(double x, double *s, double *c);

#define N 20000

static uint64_t seed = 0x9e3779b97f4a7c15ull;

/* A uniform double in [lo, hi) (xorshift64*). */
static double uniform(double lo, double hi) {
    seed ^= seed >> 12;
    seed ^= seed << 25;
    seed ^= seed >> 27;
    return lo + (hi - lo) * ((seed * 0x2545f4914f6cdd1dull) >> 11) * 0x1.0p-53;
}

static void put(double v) {
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    printf(" %016llx", (unsigned long long)bits);
}

int main(void) {
    double s, c;
    printf("cos");
    for (int i = 0; i < N; i++) put(cos(uniform(-2e4, 2e4)));
    printf("\nsincos.sin");
    for (int i = 0; i < N; i++) {
        sincos(uniform(-2e4, 2e4), &s, &c);
        put(s);
    }
    printf("\nsincos.cos");
    for (int i = 0; i < N; i++) {
        sincos(uniform(-2e4, 2e4), &s, &c);
        put(c);
    }
    printf("\nexp");
    for (int i = 0; i < N; i++) put(exp(uniform(-40.0, 40.0)));
    printf("\nlog");
    for (int i = 0; i < N; i++) {
        double m = uniform(1.0, 2.0);
        put(log(ldexp(m, (int)uniform(-40.0, 20.0))));
    }
    printf("\npow");
    for (int i = 0; i < N; i++) {
        double x = uniform(1e-3, 1e3);
        put(pow(x, uniform(-3.0, 3.0)));
    }
    printf("\natan");
    for (int i = 0; i < N; i++) put(atan(uniform(-1e3, 1e3)));
    printf("\natan2");
    for (int i = 0; i < N; i++) {
        double y = uniform(-1.0, 1.0);
        put(atan2(y, uniform(-1.0, 1.0)));
    }
    printf("\nhypot");
    for (int i = 0; i < N; i++) {
        double x = uniform(-1e3, 1e3);
        put(hypot(x, uniform(-1e3, 1e3)));
    }
    printf("\nfmod");
    for (int i = 0; i < N; i++) put(fmod(uniform(-1e5, 1e5), 6.283185307179586));
    printf("\n");
    return 0;
}
