"""The interpreter's limits on what one program may build (docs/language.md, "Limits").

A program that goes past one gets a located diagnostic, not a hang or a crash.
"""

MAX_ITER = 10_000            # iterations of one loop or comprehension
MAX_GEOMETRY = 50_000        # geometry objects in one model
MAX_TEMPLATE_DEPTH = 16      # nested template instances
