"""report_diagnosis(Component, Evidence) -> /diagnostics."""
