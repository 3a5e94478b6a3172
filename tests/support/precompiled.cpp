// The translation unit that builds tests/support/precompiled.h (flexure_test_pch); it has no code.
