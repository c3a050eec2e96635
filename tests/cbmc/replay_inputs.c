/* The free inputs of a counterexample, handed to a natively compiled harness in the order CBMC's trace
 * shows them; when they run out the counterexample is over and the harness's run ends (longjmp). */
#include <setjmp.h>
#include <stdbool.h>

#include "POUS.h"
#include "replay_inputs.h"

/* The clock and debug flag the translated ST reads, which each harness defines under CBMC. */
TIME __CURRENT_TIME;
BOOL __DEBUG;

static const unsigned long long *inputs;
static int inputCount;
static int nextInput;
static jmp_buf replayEnd;

static unsigned long long Next(void) {
    if (nextInput >= inputCount) longjmp(replayEnd, 1);
    return inputs[nextInput++];
}

_Bool nondet_bool(void) { return Next() != 0; }
unsigned char nondet_uchar(void) { return (unsigned char)Next(); }
unsigned short nondet_ushort(void) { return (unsigned short)Next(); }
unsigned int nondet_uint(void) { return (unsigned int)Next(); }

int pac_replay_run(int (*harness)(void), const unsigned long long *values, int count) {
    inputs = values;
    inputCount = count;
    nextInput = 0;
    if (setjmp(replayEnd) == 0) harness();
    return nextInput;
}
