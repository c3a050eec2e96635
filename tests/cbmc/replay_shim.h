/* Compiles a CBMC harness natively for the replay of a counterexample (test_replay.cpp): CBMC's assert and
 * assume become calls the replay records, and the harness's nondet_* functions return the counterexample's
 * free inputs in order (replay_inputs.c). Force-included (-include) into the harness, never under CBMC. */
#ifndef PAC_CBMC_REPLAY_SHIM_H
#define PAC_CBMC_REPLAY_SHIM_H
#ifdef __cplusplus
extern "C" {
#endif
void pac_replay_assert(int holds, const char *property);
void pac_replay_assume(int holds);
#ifdef __cplusplus
}
#endif
#define __CPROVER_assert(condition, property) pac_replay_assert((condition) ? 1 : 0, (property))
#define __CPROVER_assume(condition) pac_replay_assume((condition) ? 1 : 0)
#endif
