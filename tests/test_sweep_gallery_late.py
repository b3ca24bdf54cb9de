"""Every gallery entry swept across its declared ranges, second part: the generators from
``generator/i`` on (tests/test_sweep_gallery.py holds the first part and the helpers)."""
import pytest

from test_sweep_gallery import _ranged, swept_clean


@pytest.mark.parametrize("entry", _ranged(1))
def test_every_gallery_entry_is_clean_across_its_declared_ranges(entry, tmp_path):
    swept_clean(entry, tmp_path)
