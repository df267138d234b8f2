"""What a plotting call did: the files it wrote and the notes on what it skipped and why; and an
OSError said in one line, as the command line and the HTML report both say it."""
import sys


def os_error_line(e):
    """One line for an OSError: 'PATH: Permission denied', not "[Errno 13] Permission denied: 'PATH'"."""
    if e.strerror and e.filename:
        return f"{e.filename}: {e.strerror}"
    return str(e).splitlines()[0] if str(e) else type(e).__name__


class Report:
    def __init__(self, stream=None, quiet=False):
        self.written = []
        self.notes = []
        self._stream = stream
        self._quiet = quiet

    def wrote(self, paths):
        for p in paths:
            self.written.append(p)
            self._say(f"wrote {p}")

    def note(self, message):
        self.notes.append(message)
        self._say(f"note: {message}")

    def _say(self, line):
        if not self._quiet:
            print(line, file=self._stream or sys.stdout)
