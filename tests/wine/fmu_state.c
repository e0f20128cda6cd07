/* An independent FMI 2.0 importer for the FMU state tests of the Wine test
 * (tests/python/test_wine.py): the same source is compiled for Linux (gcc,
 * dlopen) and for Windows (MinGW-w64, LoadLibraryEx, run under Wine), so that
 * the linux64 and the win64 binary of one FMU go through the same calls.
 *
 *   fmu_state LIB GUID RESOURCE_URI SPEED_VR SPEED H STEPS STATE_OUT STATE_IN OUT_VR...
 *
 * Resolves all 34 fmi2 functions, then on instance A: speed SPEED (rad/s) at
 * initialization, STEPS communication steps of H s with the speed ramped by 20 %
 * over the run; at step STEPS/2 fmi2GetFMUstate and fmi2SerializeFMUstate
 * (written to STATE_OUT). The continuation is then run three times and must be
 * bit-identical: on A as it goes, on A after fmi2SetFMUstate (rollback), and on
 * a fresh instance B from the deserialized bytes. If STATE_IN is not "-", a
 * fresh instance C continues from that serialized state (written by the other
 * platform's binary). Finally the error paths: a corrupted state, a NaN input
 * and a negative step must each give fmi2Error, never a crash.
 *
 * stdout: "row K v1 v2 ..." for every step of A, "cont K ..." for C, values as
 * the hexadecimal bits of the doubles (exact); "state BYTES"; "ok" at the end.
 * A failed check prints "FAIL ..." on stderr and exits with status 1. */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _WIN32
#include <windows.h>
#else
#include <dlfcn.h>
#endif

typedef void *fmi2Component;
typedef void *fmi2FMUstate;
typedef unsigned int fmi2ValueReference;
typedef double fmi2Real;
typedef int fmi2Boolean;
typedef char fmi2Byte;
typedef int fmi2Status; /* fmi2OK 0, fmi2Warning 1, fmi2Discard 2, fmi2Error 3, fmi2Fatal 4 */
enum { fmi2OK = 0, fmi2Error = 3, fmi2CoSimulation = 1 };

typedef struct {
    void (*logger)(void *, const char *, fmi2Status, const char *, const char *, ...);
    void *(*allocateMemory)(size_t, size_t);
    void (*freeMemory)(void *);
    void (*stepFinished)(void *, fmi2Status);
    void *componentEnvironment;
} fmi2CallbackFunctions;

static const char *const NAMES[34] = {
    "fmi2GetTypesPlatform", "fmi2GetVersion", "fmi2SetDebugLogging", "fmi2Instantiate",
    "fmi2FreeInstance", "fmi2SetupExperiment", "fmi2EnterInitializationMode",
    "fmi2ExitInitializationMode", "fmi2Terminate", "fmi2Reset", "fmi2GetReal", "fmi2GetInteger",
    "fmi2GetBoolean", "fmi2GetString", "fmi2SetReal", "fmi2SetInteger", "fmi2SetBoolean",
    "fmi2SetString", "fmi2GetFMUstate", "fmi2SetFMUstate", "fmi2FreeFMUstate",
    "fmi2SerializedFMUstateSize", "fmi2SerializeFMUstate", "fmi2DeSerializeFMUstate",
    "fmi2GetDirectionalDerivative", "fmi2SetRealInputDerivatives", "fmi2GetRealOutputDerivatives",
    "fmi2DoStep", "fmi2CancelStep", "fmi2GetStatus", "fmi2GetRealStatus", "fmi2GetIntegerStatus",
    "fmi2GetBooleanStatus", "fmi2GetStringStatus"};

static struct {
    const char *(*GetVersion)(void);
    fmi2Component (*Instantiate)(const char *, int, const char *, const char *,
                                 const fmi2CallbackFunctions *, fmi2Boolean, fmi2Boolean);
    void (*FreeInstance)(fmi2Component);
    fmi2Status (*SetupExperiment)(fmi2Component, fmi2Boolean, fmi2Real, fmi2Real, fmi2Boolean,
                                  fmi2Real);
    fmi2Status (*EnterInitializationMode)(fmi2Component);
    fmi2Status (*ExitInitializationMode)(fmi2Component);
    fmi2Status (*Terminate)(fmi2Component);
    fmi2Status (*GetReal)(fmi2Component, const fmi2ValueReference *, size_t, fmi2Real *);
    fmi2Status (*SetReal)(fmi2Component, const fmi2ValueReference *, size_t, const fmi2Real *);
    fmi2Status (*GetFMUstate)(fmi2Component, fmi2FMUstate *);
    fmi2Status (*SetFMUstate)(fmi2Component, fmi2FMUstate);
    fmi2Status (*FreeFMUstate)(fmi2Component, fmi2FMUstate *);
    fmi2Status (*SerializedFMUstateSize)(fmi2Component, fmi2FMUstate, size_t *);
    fmi2Status (*SerializeFMUstate)(fmi2Component, fmi2FMUstate, fmi2Byte *, size_t);
    fmi2Status (*DeSerializeFMUstate)(fmi2Component, const fmi2Byte *, size_t, fmi2FMUstate *);
    fmi2Status (*DoStep)(fmi2Component, fmi2Real, fmi2Real, fmi2Boolean);
} fmi;

static int errors_logged;

static void logger(void *env, const char *name, fmi2Status status, const char *category,
                   const char *message, ...) {
    char text[2048];
    va_list args;
    (void)env;
    va_start(args, message);
    vsnprintf(text, sizeof text, message, args);
    va_end(args);
    if (status >= fmi2Error) errors_logged++;
    fprintf(stderr, "[%s %s %d] %s\n", name, category, status, text);
}

static void fail(const char *what) {
    fprintf(stderr, "FAIL %s\n", what);
    exit(1);
}

static void check(fmi2Status status, const char *call) {
    if (status != fmi2OK) {
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

static const fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};
static const char *guid, *uri;
static fmi2ValueReference speed_vr;
static double speed, h;
static int steps, nout;
static fmi2ValueReference *out_vr;

static fmi2Component instance(const char *name, double start_speed) {
    fmi2Component c = fmi.Instantiate(name, fmi2CoSimulation, guid, uri, &callbacks, 0, 0);
    if (!c) fail("fmi2Instantiate returned NULL");
    check(fmi.SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), "fmi2SetupExperiment");
    check(fmi.SetReal(c, &speed_vr, 1, &start_speed), "fmi2SetReal (speed)");
    check(fmi.EnterInitializationMode(c), "fmi2EnterInitializationMode");
    check(fmi.ExitInitializationMode(c), "fmi2ExitInitializationMode");
    return c;
}

/* Steps from..to-1 of the run, the outputs after step k in rows[k]. */
static void run(fmi2Component c, int from, int to, double *rows) {
    for (int k = from; k < to; k++) {
        double w = speed * (1.0 + 0.2 * k / steps);
        check(fmi.SetReal(c, &speed_vr, 1, &w), "fmi2SetReal (speed)");
        check(fmi.DoStep(c, k * h, h, 1), "fmi2DoStep");
        check(fmi.GetReal(c, out_vr, nout, rows + (size_t)k * nout), "fmi2GetReal");
    }
}

static void print_rows(const char *tag, const double *rows, int from, int to) {
    for (int k = from; k < to; k++) {
        printf("%s %d", tag, k);
        for (int j = 0; j < nout; j++) {
            uint64_t bits;
            memcpy(&bits, rows + (size_t)k * nout + j, sizeof bits);
            printf(" %016llx", (unsigned long long)bits);
        }
        printf("\n");
    }
}

static void same(const double *a, const double *b, int from, int to, const char *what) {
    size_t n = (size_t)(to - from) * nout;
    if (memcmp(a + (size_t)from * nout, b + (size_t)from * nout, n * sizeof(double)) != 0) {
        fprintf(stderr, "FAIL %s: not bit-identical to the first continuation\n", what);
        exit(1);
    }
}

int main(int argc, char **argv) {
    if (argc < 11) {
        fprintf(stderr, "usage: %s LIB GUID URI SPEED_VR SPEED H STEPS STATE_OUT STATE_IN OUT_VR...\n",
                argv[0]);
        return 2;
    }
    void *lib = load(argv[1]);
    guid = argv[2];
    uri = argv[3];
    speed_vr = (fmi2ValueReference)strtoul(argv[4], NULL, 10);
    speed = strtod(argv[5], NULL);
    h = strtod(argv[6], NULL);
    steps = atoi(argv[7]);
    const char *state_out = argv[8], *state_in = argv[9];
    nout = argc - 10;
    out_vr = malloc(sizeof *out_vr * nout);
    for (int j = 0; j < nout; j++) out_vr[j] = (fmi2ValueReference)strtoul(argv[10 + j], NULL, 10);

    for (int i = 0; i < 34; i++) symbol(lib, NAMES[i]);
    *(void **)&fmi.GetVersion = symbol(lib, "fmi2GetVersion");
    *(void **)&fmi.Instantiate = symbol(lib, "fmi2Instantiate");
    *(void **)&fmi.FreeInstance = symbol(lib, "fmi2FreeInstance");
    *(void **)&fmi.SetupExperiment = symbol(lib, "fmi2SetupExperiment");
    *(void **)&fmi.EnterInitializationMode = symbol(lib, "fmi2EnterInitializationMode");
    *(void **)&fmi.ExitInitializationMode = symbol(lib, "fmi2ExitInitializationMode");
    *(void **)&fmi.Terminate = symbol(lib, "fmi2Terminate");
    *(void **)&fmi.GetReal = symbol(lib, "fmi2GetReal");
    *(void **)&fmi.SetReal = symbol(lib, "fmi2SetReal");
    *(void **)&fmi.GetFMUstate = symbol(lib, "fmi2GetFMUstate");
    *(void **)&fmi.SetFMUstate = symbol(lib, "fmi2SetFMUstate");
    *(void **)&fmi.FreeFMUstate = symbol(lib, "fmi2FreeFMUstate");
    *(void **)&fmi.SerializedFMUstateSize = symbol(lib, "fmi2SerializedFMUstateSize");
    *(void **)&fmi.SerializeFMUstate = symbol(lib, "fmi2SerializeFMUstate");
    *(void **)&fmi.DeSerializeFMUstate = symbol(lib, "fmi2DeSerializeFMUstate");
    *(void **)&fmi.DoStep = symbol(lib, "fmi2DoStep");
    if (strcmp(fmi.GetVersion(), "2.0") != 0) fail("fmi2GetVersion is not 2.0");

    int half = steps / 2;
    double *ref = calloc((size_t)steps * nout, sizeof(double));
    double *alt = calloc((size_t)steps * nout, sizeof(double));
    fmi2Component a = instance("a", speed);
    run(a, 0, half, ref);

    fmi2FMUstate state = NULL;
    size_t size = 0;
    check(fmi.GetFMUstate(a, &state), "fmi2GetFMUstate");
    check(fmi.SerializedFMUstateSize(a, state, &size), "fmi2SerializedFMUstateSize");
    fmi2Byte *bytes = malloc(size);
    check(fmi.SerializeFMUstate(a, state, bytes, size), "fmi2SerializeFMUstate");
    FILE *f = fopen(state_out, "wb");
    if (!f || fwrite(bytes, 1, size, f) != size || fclose(f) != 0) fail("writing STATE_OUT");
    printf("state %zu\n", size);

    run(a, half, steps, ref);
    check(fmi.SetFMUstate(a, state), "fmi2SetFMUstate");
    run(a, half, steps, alt);
    same(ref, alt, half, steps, "continuation after fmi2SetFMUstate (rollback)");
    check(fmi.FreeFMUstate(a, &state), "fmi2FreeFMUstate");

    fmi2Component b = instance("b", 0.0);
    fmi2FMUstate restored = NULL;
    check(fmi.DeSerializeFMUstate(b, bytes, size, &restored), "fmi2DeSerializeFMUstate");
    check(fmi.SetFMUstate(b, restored), "fmi2SetFMUstate (deserialized)");
    check(fmi.FreeFMUstate(b, &restored), "fmi2FreeFMUstate");
    memset(alt, 0, (size_t)steps * nout * sizeof(double));
    run(b, half, steps, alt);
    same(ref, alt, half, steps, "continuation of a fresh instance from the serialized state");
    print_rows("row", ref, 0, steps);

    if (strcmp(state_in, "-") != 0) {
        f = fopen(state_in, "rb");
        if (!f) fail("opening STATE_IN");
        fseek(f, 0, SEEK_END);
        long n = ftell(f);
        fseek(f, 0, SEEK_SET);
        fmi2Byte *other = malloc(n);
        if (fread(other, 1, n, f) != (size_t)n) fail("reading STATE_IN");
        fclose(f);
        fmi2Component c = instance("c", 0.0);
        check(fmi.DeSerializeFMUstate(c, other, (size_t)n, &restored),
              "fmi2DeSerializeFMUstate (the other platform's state)");
        check(fmi.SetFMUstate(c, restored), "fmi2SetFMUstate (the other platform's state)");
        check(fmi.FreeFMUstate(c, &restored), "fmi2FreeFMUstate");
        memset(alt, 0, (size_t)steps * nout * sizeof(double));
        run(c, half, steps, alt);
        print_rows("cont", alt, half, steps);
        check(fmi.Terminate(c), "fmi2Terminate");
        fmi.FreeInstance(c);
        free(other);
    }

    /* Error paths: each an fmi2Error with a logged message, the process alive. */
    int logged = errors_logged;
    bytes[size / 2] ^= 0x5a;
    if (fmi.DeSerializeFMUstate(b, bytes, size, &restored) != fmi2Error || errors_logged == logged)
        fail("a corrupted serialized state was not refused with fmi2Error and a message");
    logged = errors_logged;
    if (fmi.DoStep(a, steps * h, -h, 1) != fmi2Error || errors_logged == logged)
        fail("a negative communication step was not refused with fmi2Error and a message");
    fmi2Component d = fmi.Instantiate("d", fmi2CoSimulation, guid, uri, &callbacks, 0, 0);
    if (!d) fail("fmi2Instantiate returned NULL");
    logged = errors_logged;
    double nan = NAN;
    if (fmi.SetReal(d, &speed_vr, 1, &nan) != fmi2Error || errors_logged == logged)
        fail("a NaN speed was not refused with fmi2Error and a message");

    fmi.FreeInstance(a);
    fmi.FreeInstance(b);
    fmi.FreeInstance(d);
    free(bytes);
    free(ref);
    free(alt);
    free(out_vr);
    printf("ok\n");
    return 0;
}
