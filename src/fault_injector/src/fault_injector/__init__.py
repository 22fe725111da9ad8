"""Fault injector service of Rason (thesis §6.3)."""
