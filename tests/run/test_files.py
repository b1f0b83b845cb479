"""certify.run.files: reading one member of a JSON object."""
from __future__ import annotations

import json

import pytest

from certify.run.files import REPORTS, first_member, read_first_member, read_text_or_none


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


TEXTS = ['{"census": {"a": [1, 2], "é": "ü€"}, "words": [1, 2, 3]}',
         ' \n{ "census" :\n{"a": [1, 2], "s": "ab,}cd"} ,"words": []}',
         '{"census": 12345, "words": []}',
         '{"census": 12345}',
         '{"words": [{"census": 0}], "census": {"a": [1, 2]}}']


@pytest.mark.parametrize("chunk", [1, 2, 3, 5, 64])
@pytest.mark.parametrize("text", TEXTS)
def test_read_first_member_is_first_member_of_the_whole_text(tmp_path, text, chunk):
    """Read in prefixes (chunks splitting the UTF-8 characters, the numbers, the strings):
    what first_member gives on the whole text."""
    path = tmp_path / "doc.json"
    path.write_text(text, encoding="utf-8")
    assert read_first_member(path, "census", chunk) == first_member(text, "census") == json.loads(text)["census"]


def test_read_first_member_missing_or_broken(tmp_path):
    """No file (or not UTF-8 where it is read): None, as read_text_or_none; a missing member
    or text that is not JSON: first_member's errors."""
    assert read_first_member(tmp_path / "none.json", "census") is None
    (tmp_path / "bad.json").write_bytes(b'{"census": "\xff"}')
    assert read_first_member(tmp_path / "bad.json", "census") is None
    (tmp_path / "w.json").write_text('{"words": []}')
    with pytest.raises(KeyError):
        read_first_member(tmp_path / "w.json", "census", 4)
    (tmp_path / "cut.json").write_text('{"census": [1, 2')
    with pytest.raises(ValueError):
        read_first_member(tmp_path / "cut.json", "census", 4)


def test_read_first_member_of_the_committed_census():
    path = REPORTS / "census.json"
    if not path.exists():
        pytest.skip("no committed census")
    assert read_first_member(path, "census") == first_member(read_text_or_none(path), "census")
