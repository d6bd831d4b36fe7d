"""Shared parts every view may use: style, messages, input guards, result tables, image export, the worker, language."""
