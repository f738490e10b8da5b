/* Cancellation and work budgets: one token per library call, polled
 * inside the work.
 *
 * A long call (a render, a measure) makes a cancel_token from the caller's
 * flag (sc_render_options.cancel: a volatile sig_atomic_t that a signal
 * handler, a viewer's event loop or a timer sets) and a budget of work.
 * Every thread that works for the call enters a cancel_scope on the token,
 * which makes the token the thread's current one. The deep loops that a
 * hostile input can make long (the implicit root finders, the mesh BVH
 * walk) know nothing of the call: they poll the current token through
 * cancel_poll every few hundred steps, and the per-pixel and per-line
 * loops poll the token itself. So a stop is seen within milliseconds of
 * the flag, wherever the time goes, without a cancel argument on every
 * primitive's span function.
 *
 * A token stops for the first of three reasons, latched: the caller's flag,
 * a single ray that exhausted its evaluation bound (SOLVE_MAX_EVALS), or
 * the call's budget of evaluations spent. The budget is an allowance up
 * front plus a credit the caller adds as its rays or lines are done, so
 * that work out of proportion to the rays fails early, after the
 * allowance, rather than at the end of a long run, and the whole call is
 * still bounded by its rays. The last two record the
 * leaf (index and primitive) whose work stopped it, for the error message.
 *
 * The current scope is a thread-local pointer, set and restored by
 * cancel_enter and cancel_leave around the work (like errno, each thread
 * has its own; nothing is shared between threads but the token, whose
 * mutable fields are atomic). Without a scope cancel_poll returns 0 and
 * the work runs as it would without this module.
 */
#ifndef SPANCAST_BASE_CANCEL_H
#define SPANCAST_BASE_CANCEL_H

#include <signal.h>
#include <stdatomic.h>
#include <stdint.h>

typedef enum cancel_reason {
    CANCEL_NONE = 0,
    CANCEL_FLAG,      /* the caller's flag was set */
    CANCEL_RAY_LIMIT, /* one ray needed more than SOLVE_MAX_EVALS evaluations */
    CANCEL_BUDGET     /* the call's budget of evaluations was spent */
} cancel_reason;

typedef struct cancel_token {
    const volatile sig_atomic_t *flag; /* the caller's; NULL: none */
    uint64_t budget;                   /* evaluations allowed up front; 0: unbounded */
    _Atomic uint64_t credit;           /* more allowed as the work goes: cancel_credit */
    _Atomic uint64_t spent;            /* evaluations reported by cancel_spend */
    _Atomic int reason;                /* cancel_reason, set once */
    _Atomic uint32_t leaf;             /* with a limit: the leaf that stopped it */
    _Atomic(const void *) prim;        /* and its primitive */
} cancel_token;

typedef struct cancel_scope {
    cancel_token *token;
    uint32_t leaf; /* what the thread works on (cancel_working_on) */
    const void *prim;
    struct cancel_scope *outer; /* the thread's previous scope, restored on leave */
} cancel_scope;

/* Makes a token for flag (may be NULL) and an allowance of evaluations
 * (0: no budget at all). */
void cancel_init(cancel_token *token, const volatile sig_atomic_t *flag, uint64_t budget);

/* Allows n more evaluations (a ray or a line is done). */
void cancel_credit(cancel_token *token, uint64_t n);

/* The reason the token stopped, CANCEL_NONE while it runs. Reads the
 * caller's flag and latches it. Cheap: two loads. */
cancel_reason cancel_check(cancel_token *token);

/* Makes token the calling thread's current one until cancel_leave(scope);
 * scopes nest. scope lives on the caller's stack. */
void cancel_enter(cancel_scope *scope, cancel_token *token);
void cancel_leave(cancel_scope *scope);

/* For the poll sites: whether the calling thread's current token has
 * stopped (0 without a current token). */
int cancel_poll(void);

/* Whether the calling thread works for a token at all. */
int cancel_active(void);

/* Names the leaf and primitive the calling thread works on now, for the
 * stops and spending below. No-op without a current token. */
void cancel_working_on(uint32_t leaf, const void *prim);

/* Stops the current token (if any, and if it has not stopped yet) for
 * reason, naming the leaf the thread works on. */
void cancel_stop(cancel_reason reason);

/* Adds n evaluations to the current token; stops it with CANCEL_BUDGET
 * when they pass its allowance and credit. No-op without a current
 * token. */
void cancel_spend(uint64_t n);

#endif
