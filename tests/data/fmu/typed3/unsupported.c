/* The FMI 3 functions typed3.c does not offer (../fmi3_unsupported.h says why they are there): the common ones,
 * the accessors of the types the lag covers, and the FMU's state (it does not declare saving it). */
#include "../fmi3_unsupported.h"

UNSUPPORTED(fmi3GetFloat64)
UNSUPPORTED(fmi3SetFloat64)
UNSUPPORTED(fmi3GetInt32)
UNSUPPORTED(fmi3SetInt32)
UNSUPPORTED(fmi3GetBoolean)
UNSUPPORTED(fmi3SetBoolean)
UNSUPPORTED(fmi3GetFMUState)
UNSUPPORTED(fmi3SetFMUState)
UNSUPPORTED(fmi3FreeFMUState)
UNSUPPORTED(fmi3SerializedFMUStateSize)
UNSUPPORTED(fmi3SerializeFMUState)
UNSUPPORTED(fmi3DeserializeFMUState)
