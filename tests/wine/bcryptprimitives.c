/* Stand-in for Windows' bcryptprimitives.dll, which Wine 8 lacks, for the Wine
 * tests only (tests/python/test_wine.py puts it next to its copy of
 * RotorBearing.dll; the shipped FMU never carries it).
 *
 * Rust's std (since 1.78) takes its random bytes from ProcessPrng in
 * bcryptprimitives.dll, present on every Windows 10 or later; here the same
 * bytes come from RtlGenRandom (advapi32's SystemFunction036). */
#include <windows.h>

BOOLEAN WINAPI SystemFunction036(PVOID buffer, ULONG length);

BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T length);

BOOL WINAPI ProcessPrng(PBYTE data, SIZE_T length) {
    while (length > 0) {
        ULONG chunk = length > 0x40000000 ? 0x40000000 : (ULONG)length;
        if (!SystemFunction036(data, chunk)) return FALSE;
        data += chunk;
        length -= chunk;
    }
    return TRUE;
}
