/* A heap limit for verification/cli/memory_limits.sh, preloaded into rsi
 * (LD_PRELOAD): malloc and its relatives return NULL with errno ENOMEM,
 * as they do when memory runs out, once a request
 *  - is larger than RSI_MAX_ALLOCATION_MB megabytes (one allocation), or
 *  - would bring the bytes allocated and not yet freed above
 *    RSI_HEAP_LIMIT_MB megabytes (the whole heap);
 * unset or 0: no limit. operator new then throws std::bad_alloc, and the C
 * libraries (CHOLMOD, LAPACKE, GSL) return their out-of-memory statuses.
 *
 * Why not `ulimit -v` (an address-space limit): OpenBLAS 0.3.21 (Debian 12)
 * retries forever when it cannot map its 128 MB buffer (blas_memory_alloc,
 * OpenBLAS issue 5289, made an exit in 0.3.30), and libgomp exits the
 * process when it cannot map a thread's stack; neither reports the failure
 * to its caller. Both reserve address space with mmap, which this limit
 * leaves alone: it limits what is allocated, as AddressSanitizer's
 * max_allocation_size_mb does in the sanitizer build (its allocator cannot
 * be interposed, so the script uses that option there instead).
 *
 * RSI_HEAP_LIMIT_REPORT=FILE: a line is appended to FILE at each refusal
 * (by open/write, which allocate nothing), so that memory_limits.sh knows
 * whether a command that completed met the limit at all.
 *
 * Test support, not part of rsi: the counters are process-wide by nature
 * (one heap), updated atomically. */

#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <malloc.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

extern void* __libc_malloc(size_t size);
extern void* __libc_calloc(size_t count, size_t size);
extern void* __libc_realloc(void* pointer, size_t size);
extern void* __libc_memalign(size_t alignment, size_t size);
extern void __libc_free(void* pointer);

static size_t live_bytes;    /* allocated and not yet freed (usable sizes) */
static int configured;       /* the limits below were read */
static size_t heap_limit;    /* bytes; 0: none */
static size_t max_allocation; /* bytes; 0: none */

static size_t megabytes(const char* name) {
  const char* text = getenv(name);
  return text ? (size_t)strtoull(text, NULL, 10) << 20 : 0;
}

static void configure(void) {
  if (__atomic_load_n(&configured, __ATOMIC_ACQUIRE)) return;
  /* getenv does not allocate: safe inside malloc. Two threads may both
   * read the same values here; harmless. */
  heap_limit = megabytes("RSI_HEAP_LIMIT_MB");
  max_allocation = megabytes("RSI_MAX_ALLOCATION_MB");
  __atomic_store_n(&configured, 1, __ATOMIC_RELEASE);
}

/* Appends a line to $RSI_HEAP_LIMIT_REPORT, if set; errno kept. */
static void report_refusal(const char* line) {
  const char* path = getenv("RSI_HEAP_LIMIT_REPORT");
  if (!path || !*path) return;
  const int saved = errno;
  const int fd = open(path, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd >= 0) {
    ssize_t written = write(fd, line, strlen(line));
    (void)written;
    close(fd);
  }
  errno = saved;
}

/* Counts `size` bytes about to be allocated; 0 (and errno ENOMEM) if a
 * limit refuses them. */
static int admit(size_t size) {
  configure();
  if (max_allocation != 0 && size > max_allocation) {
    report_refusal("refused: one allocation above RSI_MAX_ALLOCATION_MB\n");
    errno = ENOMEM;
    return 0;
  }
  if (heap_limit != 0) {
    const size_t now = __atomic_add_fetch(&live_bytes, size, __ATOMIC_RELAXED);
    if (now > heap_limit) {
      __atomic_sub_fetch(&live_bytes, size, __ATOMIC_RELAXED);
      report_refusal("refused: the live heap above RSI_HEAP_LIMIT_MB\n");
      errno = ENOMEM;
      return 0;
    }
  }
  return 1;
}

/* Replaces the `requested` bytes counted by admit with what was allocated. */
static void *counted(void* pointer, size_t requested) {
  if (heap_limit == 0) return pointer;
  const size_t usable = pointer ? malloc_usable_size(pointer) : 0;
  if (usable >= requested)
    __atomic_add_fetch(&live_bytes, usable - requested, __ATOMIC_RELAXED);
  else
    __atomic_sub_fetch(&live_bytes, requested - usable, __ATOMIC_RELAXED);
  return pointer;
}

static void uncount(void* pointer) {
  if (pointer && heap_limit != 0)
    __atomic_sub_fetch(&live_bytes, malloc_usable_size(pointer), __ATOMIC_RELAXED);
}

void* malloc(size_t size) {
  return admit(size) ? counted(__libc_malloc(size), size) : NULL;
}

void free(void* pointer) {
  uncount(pointer);
  __libc_free(pointer);
}

void* calloc(size_t count, size_t size) {
  if (size != 0 && count > (size_t)-1 / size) {
    errno = ENOMEM;
    return NULL;
  }
  return admit(count * size) ? counted(__libc_calloc(count, size), count * size) : NULL;
}

void* realloc(void* pointer, size_t size) {
  if (pointer == NULL) return malloc(size);
  if (size == 0) {
    free(pointer);
    return NULL;
  }
  const size_t old = heap_limit != 0 ? malloc_usable_size(pointer) : 0;
  if (!admit(size)) return NULL; /* the old block stays, as realloc's contract says */
  void* moved = __libc_realloc(pointer, size);
  if (moved == NULL) return counted(NULL, size);
  if (heap_limit != 0) __atomic_sub_fetch(&live_bytes, old, __ATOMIC_RELAXED);
  return counted(moved, size);
}

void* memalign(size_t alignment, size_t size) {
  return admit(size) ? counted(__libc_memalign(alignment, size), size) : NULL;
}

void* aligned_alloc(size_t alignment, size_t size) {
  return memalign(alignment, size);
}

int posix_memalign(void** out, size_t alignment, size_t size) {
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
  void* pointer = memalign(alignment, size);
  if (pointer == NULL) return ENOMEM;
  *out = pointer;
  return 0;
}

void* valloc(size_t size) {
  return memalign(4096, size);
}
