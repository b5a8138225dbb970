/* The threads' rendezvous for periodic checkpoints; see checkpoint.h. */
#include "base/parallel.h"
#include "base/util.h"
#include "io/checkpoint.h"
#include <stdlib.h>

void ckpt_sync_init(struct ckpt_sync *s, int threads, double every, void (*save)(void *ctx), void *ctx)
{
    pthread_mutex_init(&s->lock, NULL);
    pthread_cond_init(&s->wake, NULL);
    s->threads = threads;
    s->arrived = s->finished = 0;
    s->generation = 0;
    atomic_init(&s->due, false);
    s->every = every;
    atomic_init(&s->next, now_seconds() + every);
    s->slot = xcalloc((size_t)threads, sizeof *s->slot);
    s->save = save;
    s->ctx = ctx;
}

void ckpt_sync_destroy(struct ckpt_sync *s)
{
    for (int i = 0; i < s->threads; i++)
        ckpt_buf_free(&s->slot[i]);
    free(s->slot);
    pthread_cond_destroy(&s->wake);
    pthread_mutex_destroy(&s->lock);
}

bool ckpt_sync_poll(struct ckpt_sync *s)
{
    if (atomic_load_explicit(&s->due, memory_order_acquire)) return true;
    /* lock-free until the time has come: PT polls once per pixel */
    if (s->every <= 0 || now_seconds() < atomic_load_explicit(&s->next, memory_order_relaxed)) return false;
    pthread_mutex_lock(&s->lock);
    if (!atomic_load(&s->due) && now_seconds() >= atomic_load(&s->next)) atomic_store(&s->due, true);
    bool due = atomic_load(&s->due);
    pthread_mutex_unlock(&s->lock);
    return due;
}

/* With the lock held: every thread has either stored its state of this moment or finished. */
static void save_if_complete(struct ckpt_sync *s)
{
    if (!atomic_load(&s->due) || s->arrived + s->finished < s->threads) return;
    s->save(s->ctx);
    s->arrived = 0;
    atomic_store(&s->next, now_seconds() + s->every);
    atomic_store(&s->due, false);
    s->generation++;
    pthread_cond_broadcast(&s->wake);
}

void ckpt_sync_arrive(struct ckpt_sync *s)
{
    pthread_mutex_lock(&s->lock);
    unsigned gen = s->generation;
    s->arrived++;
    save_if_complete(s);
    while (s->generation == gen)
        pthread_cond_wait(&s->wake, &s->lock);
    pthread_mutex_unlock(&s->lock);
}

void ckpt_sync_finish(struct ckpt_sync *s)
{
    pthread_mutex_lock(&s->lock);
    s->finished++;
    save_if_complete(s);
    pthread_mutex_unlock(&s->lock);
}

void ckpt_save_run(struct ckpt_ctl *ctl, struct ckpt_buf *head, const struct ckpt_sync *s)
{
    for (int i = 0; i < s->threads; i++)
        ckpt_put_buf(head, &s->slot[i]);
    if (ckpt_write_file(ctl->path, &ctl->id, head, ctl->err, sizeof ctl->err))
        ctl->written = true;
    else
        interrupt_request(); /* a run whose checkpoints fail would lose what it computes */
    ckpt_buf_free(head);
}

struct ckpt_buf *ckpt_resume_threads(struct ckpt_buf *b, int threads)
{
    struct ckpt_buf *t = xcalloc((size_t)threads, sizeof *t);
    for (int i = 0; i < threads; i++)
        ckpt_get_buf(b, &t[i]);
    if (!b->short_read && b->pos == b->len) return t;
    free(t);
    return NULL;
}
