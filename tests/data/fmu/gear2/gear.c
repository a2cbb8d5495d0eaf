/* A gearbox, as an FMI 2 co-simulation FMU with Enumeration and Integer variables, for hlacore's tests: over each
 * step the gear set is engaged, speed = gear * throttle and shifts counts the changes of gear. A negative throttle
 * jams it: engaged is then 2, a value no item of the Gear type has (the case of an output beyond its type). */
#include "fmi2Functions.h"

enum { VR_GEAR = 0, VR_THROTTLE = 1, VR_SPEED = 2, VR_ENGAGED = 3, VR_SHIFTS = 4, MODEL_VALUES = 5 };

static void model_start(double v[]) { (void)v; }
static void model_initialize(double v[]) {
    v[VR_ENGAGED] = v[VR_GEAR];
    v[VR_SPEED] = v[VR_GEAR] * v[VR_THROTTLE];
}
static int model_settable(fmi2ValueReference vr) { return vr == VR_GEAR || vr == VR_THROTTLE; }

static int model_step(double v[], double t, double h) {
    (void)t; (void)h;
    v[VR_SHIFTS] += v[VR_GEAR] != v[VR_ENGAGED];
    v[VR_ENGAGED] = v[VR_THROTTLE] < 0 ? 2 : v[VR_GEAR];
    v[VR_SPEED] = v[VR_GEAR] * v[VR_THROTTLE];
    return 0;
}

#define MODEL_INTEGER(vr) ((vr) == VR_GEAR || (vr) == VR_ENGAGED || (vr) == VR_SHIFTS)
#include "hlacore_fmi2.h"
