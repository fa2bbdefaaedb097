/*
 * The entries' one kind of lock, statically initialised: a pthread mutex on
 * POSIX; on Windows a slim reader/writer lock taken exclusively, which
 * kernel32 provides, so that usrsub.dll needs no threads library beside it
 * (docs/windows.md). Only set-ups and error reports lock: never the call path.
 */
#ifndef USRSUB_MUTEX_H
#define USRSUB_MUTEX_H

#ifdef _WIN32
/* The layout of an SRWLOCK (one pointer, zero when unlocked), so that this
 * header need not include windows.h and its macros. */
typedef struct usrsub_mutex {
    void *srwlock;
} usrsub_mutex;
#define USRSUB_MUTEX_INIT {0}
#else
#include <pthread.h>
typedef pthread_mutex_t usrsub_mutex;
#define USRSUB_MUTEX_INIT PTHREAD_MUTEX_INITIALIZER
#endif

void usrsub_mutex_lock(usrsub_mutex *m);
void usrsub_mutex_unlock(usrsub_mutex *m);

#endif
