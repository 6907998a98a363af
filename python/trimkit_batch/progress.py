"""The terminal progress line: files done of the total, failed, skipped, the rate of
conversion and the time left. On a terminal one line is rewritten in place; into a log
a line is printed at most every LOG_SECONDS, and at the end. Each failure also gets a
line of its own: "trimkit-batch: FILE: reason"."""
import sys
import time

from .outcome import FAILED, SKIPPED

LOG_SECONDS = 10.0


class Progress:
    def __init__(self, total, stream=None):
        self.total = total
        self.stream = stream or sys.stderr
        self.tty = self.stream.isatty()
        self.done = self.failed = self.skipped = 0
        self.parts_done = self.parts_total = 0
        self.start = time.monotonic()
        self._last_line = 0.0

    def file_done(self, job, outcome):
        self.done += 1
        if outcome.status == FAILED:
            self.failed += 1
            error = outcome.error or "failed"
            self._print(f"trimkit-batch: {error if error.startswith(job.input) else job.input + ': ' + error}")
        elif outcome.status == SKIPPED:
            self.skipped += 1
        self.show()

    def parts_planned(self, count):
        self.parts_total += count
        self.show()

    def part_done(self):
        self.parts_done += 1
        self.show()

    def line(self):
        elapsed = time.monotonic() - self.start
        converted = self.done - self.skipped
        rate = converted / elapsed if elapsed > 0.0 else 0.0
        left = self.total - self.done
        eta = f", {left / rate:.0f} s left" if rate > 0.0 and left else ""
        parts = f", parts {self.parts_done}/{self.parts_total}" if self.parts_total else ""
        return (f"[{self.done}/{self.total}] {self.failed} failed, {self.skipped} skipped{parts}, "
                f"{rate:.2f} files/s{eta}, {elapsed:.1f} s")

    def show(self, force=False):
        now = time.monotonic()
        if self.tty:
            self.stream.write("\r" + self.line() + "\033[K")
            self.stream.flush()
        elif force or now - self._last_line >= LOG_SECONDS:
            self._last_line = now
            self._print(self.line())

    def finish(self):
        if self.tty:
            self.show()
            self.stream.write("\n")
            self.stream.flush()
        else:
            self.show(force=True)

    def _print(self, text):
        if self.tty:
            self.stream.write("\r\033[K")
        self.stream.write(text + "\n")
        self.stream.flush()
