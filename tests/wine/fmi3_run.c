/* An independent FMI 3.0 importer for the FMI 3.0 part of the Wine test
 * (tests/python/test_wine_fmi3.py): the same source is compiled for Linux (gcc,
 * dlopen) and for Windows (MinGW-w64, LoadLibraryEx, run under Wine), so that
 * the linux64 and the win64 binary of one FMU go through the same calls.
 *
 *   fmi3_run LIB TOKEN RESOURCE_PATH PLAN
 *
 * PLAN is a text file, every real the hexadecimal bits of a double (exact on
 * both platforms):
 *   outputs N VR...                the outputs read after initialization and
 *                                  after each step
 *   init N VR KIND VALUE ...       set before fmi3EnterInitializationMode
 *                                  (KIND f: a real, fmi3SetFloat64; i: a
 *                                  decimal integer, fmi3SetInt32)
 *   step T H N VR KIND VALUE ...   set these inputs, then fmi3DoStep(T, H)
 * Instantiates a Co-Simulation instance (no early return, no intermediate
 * updates), initializes at time 0, runs the plan and prints "row K v1 v2 ..."
 * (the hexadecimal bits of the outputs) after initialization (K = 0) and after
 * each step, then "ok". A call that does not return fmi3OK (or fmi3Warning),
 * or a step that does not end where it was asked to, prints "FAIL ..." on
 * stderr and exits with status 1. */
#include <inttypes.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _WIN32
#include <windows.h>
#else
#include <dlfcn.h>
#endif

typedef void *fmi3Instance;
typedef unsigned int fmi3ValueReference;
typedef double fmi3Float64;
typedef int fmi3Status; /* fmi3OK 0, fmi3Warning 1, fmi3Discard 2, fmi3Error 3, fmi3Fatal 4 */
typedef _Bool fmi3Boolean;
enum { fmi3OK = 0, fmi3Warning = 1 };

typedef void (*fmi3LogMessageCallback)(void *, fmi3Status, const char *, const char *);

static struct {
    fmi3Instance (*InstantiateCoSimulation)(const char *, const char *, const char *, fmi3Boolean,
                                            fmi3Boolean, fmi3Boolean, fmi3Boolean,
                                            const fmi3ValueReference *, size_t, void *,
                                            fmi3LogMessageCallback, void *);
    void (*FreeInstance)(fmi3Instance);
    fmi3Status (*EnterInitializationMode)(fmi3Instance, fmi3Boolean, fmi3Float64, fmi3Float64,
                                          fmi3Boolean, fmi3Float64);
    fmi3Status (*ExitInitializationMode)(fmi3Instance);
    fmi3Status (*Terminate)(fmi3Instance);
    fmi3Status (*GetFloat64)(fmi3Instance, const fmi3ValueReference *, size_t, fmi3Float64 *,
                             size_t);
    fmi3Status (*SetFloat64)(fmi3Instance, const fmi3ValueReference *, size_t,
                             const fmi3Float64 *, size_t);
    fmi3Status (*SetInt32)(fmi3Instance, const fmi3ValueReference *, size_t, const int32_t *,
                           size_t);
    fmi3Status (*DoStep)(fmi3Instance, fmi3Float64, fmi3Float64, fmi3Boolean, fmi3Boolean *,
                         fmi3Boolean *, fmi3Boolean *, fmi3Float64 *);
} fmi;

static void logger(void *env, fmi3Status status, const char *category, const char *message) {
    (void)env;
    if (status > fmi3Warning) fprintf(stderr, "[%s %d] %s\n", category, status, message);
}

static void check(fmi3Status status, const char *call) {
    if (status != fmi3OK && status != fmi3Warning) {
        fprintf(stderr, "FAIL %s returned status %d\n", call, status);
        exit(1);
    }
}

static void *load(const char *path) {
#ifdef _WIN32
    /* As importers do: the DLL's own folder is searched for its imports. */
    HMODULE lib = LoadLibraryExA(path, NULL, LOAD_WITH_ALTERED_SEARCH_PATH);
    if (!lib) {
        fprintf(stderr, "FAIL LoadLibraryEx %s: error %lu\n", path, GetLastError());
        exit(1);
    }
    return (void *)lib;
#else
    void *lib = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        fprintf(stderr, "FAIL dlopen %s: %s\n", path, dlerror());
        exit(1);
    }
    return lib;
#endif
}

static void *symbol(void *lib, const char *name) {
#ifdef _WIN32
    void *f = (void *)GetProcAddress((HMODULE)lib, name);
#else
    void *f = dlsym(lib, name);
#endif
    if (!f) {
        fprintf(stderr, "FAIL %s is not exported\n", name);
        exit(1);
    }
    return f;
}

/* The next number of the plan: a count or a value reference (decimal), or a
 * double (hexadecimal bits). */
static unsigned long next_count(FILE *f) {
    unsigned long n;
    if (fscanf(f, "%lu", &n) != 1) {
        fprintf(stderr, "FAIL plan: a count or value reference expected\n");
        exit(1);
    }
    return n;
}

static double next_double(FILE *f) {
    char word[32];
    if (fscanf(f, "%31s", word) != 1) {
        fprintf(stderr, "FAIL plan: a value expected\n");
        exit(1);
    }
    uint64_t bits = strtoull(word, NULL, 16);
    double x;
    memcpy(&x, &bits, sizeof x);
    return x;
}

/* Read N entries "VR KIND VALUE" and set them. */
static void set_inputs(fmi3Instance c, FILE *f) {
    unsigned long n = next_count(f);
    for (unsigned long k = 0; k < n; k++) {
        fmi3ValueReference vr = (fmi3ValueReference)next_count(f);
        char kind[4];
        if (fscanf(f, "%3s", kind) != 1) {
            fprintf(stderr, "FAIL plan: a kind (f, i) expected\n");
            exit(1);
        }
        if (strcmp(kind, "i") == 0) {
            int32_t v = (int32_t)next_count(f);
            check(fmi.SetInt32(c, &vr, 1, &v, 1), "fmi3SetInt32");
        } else {
            double v = next_double(f);
            check(fmi.SetFloat64(c, &vr, 1, &v, 1), "fmi3SetFloat64");
        }
    }
}

static size_t nout;
static fmi3ValueReference *out_vr;
static double *values;

static void print_row(fmi3Instance c, int k) {
    check(fmi.GetFloat64(c, out_vr, nout, values, nout), "fmi3GetFloat64");
    printf("row %d", k);
    for (size_t j = 0; j < nout; j++) {
        uint64_t bits;
        memcpy(&bits, values + j, sizeof bits);
        printf(" %016" PRIx64, bits);
    }
    printf("\n");
}

int main(int argc, char **argv) {
    if (argc != 5) {
        fprintf(stderr, "usage: %s LIB TOKEN RESOURCE_PATH PLAN\n", argv[0]);
        return 2;
    }
    void *lib = load(argv[1]);
    *(void **)&fmi.InstantiateCoSimulation = symbol(lib, "fmi3InstantiateCoSimulation");
    *(void **)&fmi.FreeInstance = symbol(lib, "fmi3FreeInstance");
    *(void **)&fmi.EnterInitializationMode = symbol(lib, "fmi3EnterInitializationMode");
    *(void **)&fmi.ExitInitializationMode = symbol(lib, "fmi3ExitInitializationMode");
    *(void **)&fmi.Terminate = symbol(lib, "fmi3Terminate");
    *(void **)&fmi.GetFloat64 = symbol(lib, "fmi3GetFloat64");
    *(void **)&fmi.SetFloat64 = symbol(lib, "fmi3SetFloat64");
    *(void **)&fmi.SetInt32 = symbol(lib, "fmi3SetInt32");
    *(void **)&fmi.DoStep = symbol(lib, "fmi3DoStep");
    FILE *plan = fopen(argv[4], "r");
    if (!plan) {
        fprintf(stderr, "FAIL cannot open %s\n", argv[4]);
        return 1;
    }
    fmi3Instance c = fmi.InstantiateCoSimulation("wine", argv[2], argv[3], 0, 0, 0, 0, NULL, 0,
                                                 NULL, logger, NULL);
    if (!c) {
        fprintf(stderr, "FAIL fmi3InstantiateCoSimulation returned NULL\n");
        return 1;
    }
    char word[16];
    int k = 0;
    while (fscanf(plan, "%15s", word) == 1) {
        if (strcmp(word, "outputs") == 0) {
            nout = next_count(plan);
            out_vr = calloc(nout, sizeof *out_vr);
            values = calloc(nout, sizeof *values);
            if (!out_vr || !values) return 1;
            for (size_t j = 0; j < nout; j++) out_vr[j] = (fmi3ValueReference)next_count(plan);
        } else if (strcmp(word, "init") == 0) {
            set_inputs(c, plan);
            check(fmi.EnterInitializationMode(c, 0, 0.0, 0.0, 0, 0.0),
                  "fmi3EnterInitializationMode");
            check(fmi.ExitInitializationMode(c), "fmi3ExitInitializationMode");
            print_row(c, k++);
        } else if (strcmp(word, "step") == 0) {
            double t = next_double(plan), h = next_double(plan);
            set_inputs(c, plan);
            fmi3Boolean event, terminate, early;
            double last;
            check(fmi.DoStep(c, t, h, 1, &event, &terminate, &early, &last), "fmi3DoStep");
            if (early || event || terminate || last != t + h) {
                fprintf(stderr, "FAIL fmi3DoStep(%.17g, %.17g) stopped at %.17g\n", t, h, last);
                return 1;
            }
            print_row(c, k++);
        } else {
            fprintf(stderr, "FAIL plan: unknown line %s\n", word);
            return 1;
        }
    }
    check(fmi.Terminate(c), "fmi3Terminate");
    fmi.FreeInstance(c);
    printf("ok\n");
    return 0;
}
