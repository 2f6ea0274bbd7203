"""Helpers the tests share (imported as ``support.<module>``; conftest.py puts tests/python on the
path)."""
