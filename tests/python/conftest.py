"""Hypothesis settings for the gdel Python tests (helpers live in helpers.py)."""

import os

from hypothesis import HealthCheck, settings

# CI-sized property runs; GDEL_HYPOTHESIS_EXAMPLES raises the count locally.
settings.register_profile(
    "gdel",
    max_examples=int(os.environ.get("GDEL_HYPOTHESIS_EXAMPLES", "40")),
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.load_profile("gdel")
