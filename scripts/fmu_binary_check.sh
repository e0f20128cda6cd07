#!/usr/bin/env bash
# Checks an FMU binary before fmu_pack.sh packs it:
#
#   bash scripts/fmu_binary_check.sh LIB.so|LIB.dll
#   bash scripts/fmu_binary_check.sh --fmi 2|3 LIB.so|LIB.dll
#
# Both kinds must export all 34 functions of an FMI 2.0 co-simulation FMU
# (fmi2Functions.h: 25 common, 9 co-simulation), with --fmi 3 all 75 functions
# of fmi3Functions.h instead (the same library carries both); a DLL must also import system
# DLLs only, since no MinGW runtime DLL (libgcc_s_seh-1.dll,
# libwinpthread-1.dll, ...) travels with the FMU. Prints what it checked; on a
# failure, names the missing functions or the foreign DLLs and exits with 1.
set -euo pipefail
fmi=2
if [ $# -eq 3 ] && [ "$1" = --fmi ] && { [ "$2" = 2 ] || [ "$2" = 3 ]; }; then fmi=$2; shift 2; fi
[ $# -eq 1 ] && [ -f "$1" ] || { echo "usage: $0 [--fmi 2|3] LIB.so|LIB.dll (an existing file)" >&2; exit 2; }
lib=$1

required="fmi2GetTypesPlatform fmi2GetVersion fmi2SetDebugLogging fmi2Instantiate fmi2FreeInstance
fmi2SetupExperiment fmi2EnterInitializationMode fmi2ExitInitializationMode fmi2Terminate fmi2Reset
fmi2GetReal fmi2GetInteger fmi2GetBoolean fmi2GetString fmi2SetReal fmi2SetInteger fmi2SetBoolean
fmi2SetString fmi2GetFMUstate fmi2SetFMUstate fmi2FreeFMUstate fmi2SerializedFMUstateSize
fmi2SerializeFMUstate fmi2DeSerializeFMUstate fmi2GetDirectionalDerivative
fmi2SetRealInputDerivatives fmi2GetRealOutputDerivatives fmi2DoStep fmi2CancelStep fmi2GetStatus
fmi2GetRealStatus fmi2GetIntegerStatus fmi2GetBooleanStatus fmi2GetStringStatus"
fmi3_required="fmi3GetVersion fmi3SetDebugLogging fmi3InstantiateModelExchange fmi3InstantiateCoSimulation
fmi3InstantiateScheduledExecution fmi3FreeInstance fmi3EnterInitializationMode
fmi3ExitInitializationMode fmi3EnterEventMode fmi3Terminate fmi3Reset fmi3GetFloat32 fmi3GetFloat64
fmi3GetInt8 fmi3GetUInt8 fmi3GetInt16 fmi3GetUInt16 fmi3GetInt32 fmi3GetUInt32 fmi3GetInt64
fmi3GetUInt64 fmi3GetBoolean fmi3GetString fmi3GetBinary fmi3GetClock fmi3SetFloat32 fmi3SetFloat64
fmi3SetInt8 fmi3SetUInt8 fmi3SetInt16 fmi3SetUInt16 fmi3SetInt32 fmi3SetUInt32 fmi3SetInt64
fmi3SetUInt64 fmi3SetBoolean fmi3SetString fmi3SetBinary fmi3SetClock
fmi3GetNumberOfVariableDependencies fmi3GetVariableDependencies fmi3GetFMUState fmi3SetFMUState
fmi3FreeFMUState fmi3SerializedFMUStateSize fmi3SerializeFMUState fmi3DeserializeFMUState
fmi3GetDirectionalDerivative fmi3GetAdjointDerivative fmi3EnterConfigurationMode
fmi3ExitConfigurationMode fmi3GetIntervalDecimal fmi3GetIntervalFraction fmi3GetShiftDecimal
fmi3GetShiftFraction fmi3SetIntervalDecimal fmi3SetIntervalFraction fmi3SetShiftDecimal
fmi3SetShiftFraction fmi3EvaluateDiscreteStates fmi3UpdateDiscreteStates
fmi3EnterContinuousTimeMode fmi3CompletedIntegratorStep fmi3SetTime fmi3SetContinuousStates
fmi3GetContinuousStateDerivatives fmi3GetEventIndicators fmi3GetContinuousStates
fmi3GetNominalsOfContinuousStates fmi3GetNumberOfEventIndicators fmi3GetNumberOfContinuousStates
fmi3EnterStepMode fmi3GetOutputDerivatives fmi3DoStep fmi3ActivateModelPartition"
if [ "$fmi" = 3 ]; then required=$fmi3_required; fi
# DLLs of every Windows 10 or later (the oldest Windows Rust's std runs on).
system_dlls="kernel32.dll ntdll.dll msvcrt.dll userenv.dll ws2_32.dll advapi32.dll bcrypt.dll
bcryptprimitives.dll api-ms-win-core-synch-l1-2-0.dll"

case "$lib" in
  *.so)
    exported=$(nm -D --defined-only "$lib" | awk '$2 == "T" && $3 ~ /^fmi[23]/ { print $3 }') ;;
  *.dll)
    command -v x86_64-w64-mingw32-objdump >/dev/null 2>&1 \
      || { echo "$0: x86_64-w64-mingw32-objdump not found: run scripts/setup.sh" >&2; exit 2; }
    pe=$(x86_64-w64-mingw32-objdump -p "$lib")
    exported=$(awk '/^\[Ordinal\/Name Pointer\] Table/ { t = 1; next } t && NF == 0 { t = 0 }
      t && $NF ~ /^fmi[23]/ { print $NF }' <<< "$pe") ;;
  *) echo "$0: $lib is neither a .so nor a .dll" >&2; exit 2 ;;
esac
missing=$(comm -23 <(tr ' ' '\n' <<< "$required" | sort) <(sort -u <<< "$exported") | tr '\n' ' ')
[ -z "$missing" ] || { echo "$lib does not export ${missing% }" >&2; exit 1; }
if [ "$fmi" = 3 ]; then report="75 fmi3 functions exported"; else report="34 fmi2 functions exported"; fi
if [ "${lib%.dll}" != "$lib" ]; then
  imports=$(awk '/DLL Name:/ { print $3 }' <<< "$pe" | sort -fu | tr '\n' ' ')
  foreign=$(for d in $imports; do tr ' ' '\n' <<< "$system_dlls" | grep -qixF "$d" || echo "$d"; done | tr '\n' ' ')
  [ -z "$foreign" ] || { echo "$lib imports DLLs that are not part of Windows: ${foreign% }" >&2; exit 1; }
  report="$report, system DLLs imported only (${imports% })"
fi
echo "$lib: $report"
