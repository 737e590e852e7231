"""Report: the problems found (each names its file and says what to fix) and notes on coverage."""


class Report:
    def __init__(self):
        self.problems = []
        self.notes = []

    def problem(self, where, message):
        self.problems.append(f"{where}: {message}")
