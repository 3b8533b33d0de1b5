// Stub: implementation in progress.
