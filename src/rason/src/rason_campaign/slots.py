"""Runs a list of jobs on a few numbered slots at once (the campaign's --jobs): each slot
is one ROS master port range, so two runs at the same time never pick the same port."""
import queue
import threading
from concurrent.futures import ThreadPoolExecutor


def run_in_slots(items, slots, work, done=None, interrupted=None):
    """``work(item, slot)`` for every item, at most ``slots`` at a time, each slot number
    (0 .. slots - 1) held by one item at a time; ``done(index, item, value)`` as each ends
    (under a lock, so its prints do not interleave). Returns the values in the items' order.
    An exception of ``work`` is raised here once the items already started have ended; no
    further item starts after it. On Ctrl-C, ``interrupted()`` is called (to stop the work
    under way), then the KeyboardInterrupt goes on once that work has ended.

    :param slots: int >= 1
    """
    if slots < 1:
        raise ValueError('slots must be >= 1, got %r' % (slots,))
    free = queue.Queue()
    for slot in range(slots):
        free.put(slot)
    lock = threading.Lock()
    failed = threading.Event()
    values = [None] * len(items)

    def one(index, item):
        if failed.is_set():
            return
        slot = free.get()
        try:
            value = work(item, slot)
        except BaseException:
            failed.set()
            raise
        finally:
            free.put(slot)
        values[index] = value
        if done is not None:
            with lock:
                done(index, item, value)

    pool = ThreadPoolExecutor(max_workers=slots)
    try:
        futures = [pool.submit(one, i, item) for i, item in enumerate(items)]
        for future in futures:
            future.result()
    except KeyboardInterrupt:
        failed.set()
        if interrupted is not None:
            interrupted()
        raise
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
    return values
