# expect: W0104
