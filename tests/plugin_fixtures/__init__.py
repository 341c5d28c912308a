"""Test fixtures for the transport and plugin tests (a facts world, Zenoh helpers)."""
