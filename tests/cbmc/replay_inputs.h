/* Runs a natively compiled CBMC harness on a counterexample's free inputs (replay_inputs.c). */
#ifndef PAC_CBMC_REPLAY_INPUTS_H
#define PAC_CBMC_REPLAY_INPUTS_H
#ifdef __cplusplus
extern "C" {
#endif
/* Calls harness() until it returns or the inputs run out; returns how many inputs it used. */
int pac_replay_run(int (*harness)(void), const unsigned long long *values, int count);
#ifdef __cplusplus
}
#endif
#endif
