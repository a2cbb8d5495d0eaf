/* A first-order lag as an FMI 2 co-simulation FMU, for hlacore's tests: dx/dt = (u - x) / tau, y = x, over
 * hlacore's FMI 2 skeleton (python/hlacore/fmu/c/hlacore_fmi2.h), which also makes its state (x, time) readable,
 * restorable and serialisable, so a federation save includes it.
 *
 * doStep integrates exactly over the step with u held constant, so a run's result depends on the step size
 * only through the inputs. Two test parameters make it misbehave on purpose: from fail_time on, doStep
 * fails; from nan_time on, y becomes NaN. Value references are those of modelDescription.xml. */
#include <math.h>

#include "fmi2Functions.h"

enum { VR_U = 0, VR_Y = 1, VR_TAU = 2, VR_X0 = 3, VR_FAIL_TIME = 4, VR_NAN_TIME = 5, MODEL_VALUES = 6 };

static void model_start(double v[]) {
    v[VR_TAU] = 1.0;
    v[VR_FAIL_TIME] = INFINITY;
    v[VR_NAN_TIME] = INFINITY;
}

static void model_initialize(double v[]) { v[VR_Y] = v[VR_X0]; }

static int model_settable(fmi2ValueReference vr) { return vr != VR_Y; }

static int model_step(double v[], double t, double h) {
    if (t >= v[VR_FAIL_TIME]) return -1;
    double x = v[VR_Y], u = v[VR_U];
    x = u + (x - u) * exp(-h / v[VR_TAU]);
    v[VR_Y] = t + h >= v[VR_NAN_TIME] ? NAN : x;
    return 0;
}

#include "hlacore_fmi2.h"
