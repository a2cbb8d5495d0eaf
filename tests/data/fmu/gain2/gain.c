/* A gain, y = k u, as an FMI 2 co-simulation FMU with direct feedthrough, for hlacore's tests: y follows u as
 * soon as u is set (model_outputs, called before each get), so the federate sends y at the time of u. */
#include "fmi2Functions.h"

enum { VR_U = 0, VR_Y = 1, VR_K = 2, MODEL_VALUES = 3 };

static void model_start(double v[]) { v[VR_K] = 2.0; }
static void model_outputs(double v[]) { v[VR_Y] = v[VR_K] * v[VR_U]; }
static void model_initialize(double v[]) { model_outputs(v); }
static int model_settable(fmi2ValueReference vr) { return vr != VR_Y; }

static int model_step(double v[], double t, double h) {
    (void)t; (void)h;
    model_outputs(v);
    return 0;
}

#define MODEL_OUTPUTS model_outputs
#include "hlacore_fmi2.h"
