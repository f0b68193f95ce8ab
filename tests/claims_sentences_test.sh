#!/bin/bash
# ctest entry for tests/claims_sentences_test.py (the first claim's sentences against their intervals).
exec /usr/bin/python3 "$2/tests/claims_sentences_test.py" "$2"
