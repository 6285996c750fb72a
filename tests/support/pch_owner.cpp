// The one source of niwa_test_pch, the object library that owns the tests' precompiled header.
