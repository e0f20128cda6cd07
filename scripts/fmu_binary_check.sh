#!/usr/bin/env bash
# Checks an FMU binary before fmu_pack.sh packs it:
#
#   bash scripts/fmu_binary_check.sh LIB.so|LIB.dll
#
# Both kinds must export all 34 functions of an FMI 2.0 co-simulation FMU
# (fmi2Functions.h: 25 common, 9 co-simulation); a DLL must also import system
# DLLs only, since no MinGW runtime DLL (libgcc_s_seh-1.dll,
# libwinpthread-1.dll, ...) travels with the FMU. Prints what it checked; on a
# failure, names the missing functions or the foreign DLLs and exits with 1.
set -euo pipefail
[ $# -eq 1 ] && [ -f "$1" ] || { echo "usage: $0 LIB.so|LIB.dll (an existing file)" >&2; exit 2; }
lib=$1

required="fmi2GetTypesPlatform fmi2GetVersion fmi2SetDebugLogging fmi2Instantiate fmi2FreeInstance
fmi2SetupExperiment fmi2EnterInitializationMode fmi2ExitInitializationMode fmi2Terminate fmi2Reset
fmi2GetReal fmi2GetInteger fmi2GetBoolean fmi2GetString fmi2SetReal fmi2SetInteger fmi2SetBoolean
fmi2SetString fmi2GetFMUstate fmi2SetFMUstate fmi2FreeFMUstate fmi2SerializedFMUstateSize
fmi2SerializeFMUstate fmi2DeSerializeFMUstate fmi2GetDirectionalDerivative
fmi2SetRealInputDerivatives fmi2GetRealOutputDerivatives fmi2DoStep fmi2CancelStep fmi2GetStatus
fmi2GetRealStatus fmi2GetIntegerStatus fmi2GetBooleanStatus fmi2GetStringStatus"
# DLLs of every Windows 10 or later (the oldest Windows Rust's std runs on).
system_dlls="kernel32.dll ntdll.dll msvcrt.dll userenv.dll ws2_32.dll advapi32.dll bcrypt.dll
bcryptprimitives.dll api-ms-win-core-synch-l1-2-0.dll"

case "$lib" in
  *.so)
    exported=$(nm -D --defined-only "$lib" | awk '$2 == "T" && $3 ~ /^fmi2/ { print $3 }') ;;
  *.dll)
    command -v x86_64-w64-mingw32-objdump >/dev/null 2>&1 \
      || { echo "$0: x86_64-w64-mingw32-objdump not found: run scripts/setup.sh" >&2; exit 2; }
    pe=$(x86_64-w64-mingw32-objdump -p "$lib")
    exported=$(awk '/^\[Ordinal\/Name Pointer\] Table/ { t = 1; next } t && NF == 0 { t = 0 }
      t && $NF ~ /^fmi2/ { print $NF }' <<< "$pe") ;;
  *) echo "$0: $lib is neither a .so nor a .dll" >&2; exit 2 ;;
esac
missing=$(comm -23 <(tr ' ' '\n' <<< "$required" | sort) <(sort -u <<< "$exported") | tr '\n' ' ')
[ -z "$missing" ] || { echo "$lib does not export ${missing% }" >&2; exit 1; }
report="34 fmi2 functions exported"
if [ "${lib%.dll}" != "$lib" ]; then
  imports=$(awk '/DLL Name:/ { print $3 }' <<< "$pe" | sort -fu | tr '\n' ' ')
  foreign=$(for d in $imports; do tr ' ' '\n' <<< "$system_dlls" | grep -qixF "$d" || echo "$d"; done | tr '\n' ' ')
  [ -z "$foreign" ] || { echo "$lib imports DLLs that are not part of Windows: ${foreign% }" >&2; exit 1; }
  report="$report, system DLLs imported only (${imports% })"
fi
echo "$lib: $report"
