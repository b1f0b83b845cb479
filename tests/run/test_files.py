"""certify.run.files: reading one member of a JSON object."""
from __future__ import annotations

import json

import pytest

from certify.run.files import first_member


@pytest.mark.parametrize("text", ['{"census": {"a": [1, 2]}, "words": [1, 2, 3]}',
                                  ' \n{ "census" :\n{"a": [1, 2]} ,"words": []}',
                                  '{"words": [{"census": 0}], "census": {"a": [1, 2]}}'])
def test_first_member_is_the_whole_parse(text):
    """The first member decoded alone, or another one by the whole parse: json.loads's value."""
    assert first_member(text, "census") == json.loads(text)["census"] == {"a": [1, 2]}


def test_first_member_missing_or_broken():
    """A missing member is a KeyError, text that is not JSON a ValueError (as json.loads)."""
    with pytest.raises(KeyError):
        first_member('{"words": []}', "census")
    with pytest.raises(KeyError):
        first_member("{}", "census")
    with pytest.raises(ValueError):
        first_member('{"census": [1, 2', "census")
