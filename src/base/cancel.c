/* Cancellation tokens and the calling thread's current one: see cancel.h.
 *
 * The only state outside a token is the thread-local pointer to the
 * thread's innermost scope, which a poll site reads to find its token.
 * Tokens are written with relaxed atomics: a stop is a one-way latch that
 * other threads need only see soon, not in any order with other memory.
 */
#include "base/cancel.h"

#include <stddef.h>

static _Thread_local cancel_scope *current_scope;

void cancel_init(cancel_token *token, const volatile sig_atomic_t *flag, uint64_t budget)
{
    token->flag = flag;
    token->budget = budget;
    atomic_init(&token->credit, 0);
    atomic_init(&token->spent, 0);
    atomic_init(&token->reason, CANCEL_NONE);
    atomic_init(&token->leaf, 0);
    atomic_init(&token->prim, NULL);
}

static void latch(cancel_token *token, cancel_reason reason, uint32_t leaf,
                  const void *prim)
{
    int none = CANCEL_NONE;
    if (atomic_compare_exchange_strong(&token->reason, &none, (int)reason)) {
        atomic_store_explicit(&token->leaf, leaf, memory_order_relaxed);
        atomic_store_explicit(&token->prim, prim, memory_order_relaxed);
    }
}

void cancel_credit(cancel_token *token, uint64_t n)
{
    if (token->budget)
        atomic_fetch_add_explicit(&token->credit, n, memory_order_relaxed);
}

cancel_reason cancel_check(cancel_token *token)
{
    int reason = atomic_load_explicit(&token->reason, memory_order_relaxed);
    if (reason != CANCEL_NONE)
        return (cancel_reason)reason;
    if (token->flag && *token->flag) {
        latch(token, CANCEL_FLAG, 0, NULL);
        return (cancel_reason)atomic_load(&token->reason);
    }
    return CANCEL_NONE;
}

void cancel_enter(cancel_scope *scope, cancel_token *token)
{
    scope->token = token;
    scope->leaf = 0;
    scope->prim = NULL;
    scope->outer = current_scope;
    current_scope = scope;
}

void cancel_leave(cancel_scope *scope)
{
    current_scope = scope->outer;
}

int cancel_poll(void)
{
    cancel_scope *s = current_scope;
    return s && cancel_check(s->token) != CANCEL_NONE;
}

int cancel_active(void)
{
    return current_scope != NULL;
}

void cancel_working_on(uint32_t leaf, const void *prim)
{
    cancel_scope *s = current_scope;
    if (s) {
        s->leaf = leaf;
        s->prim = prim;
    }
}

void cancel_stop(cancel_reason reason)
{
    cancel_scope *s = current_scope;
    if (s)
        latch(s->token, reason, s->leaf, s->prim);
}

void cancel_spend(uint64_t n)
{
    cancel_scope *s = current_scope;
    if (!s || !s->token->budget)
        return;
    uint64_t spent =
        atomic_fetch_add_explicit(&s->token->spent, n, memory_order_relaxed) + n;
    if (spent > s->token->budget &&
        spent - s->token->budget >
            atomic_load_explicit(&s->token->credit, memory_order_relaxed))
        latch(s->token, CANCEL_BUDGET, s->leaf, s->prim);
}
