"""The CLI's output texts as pandas frames and dicts: read, never re-derived."""

import io
import json

import pandas as pd


def frame(csv_text: str) -> pd.DataFrame:
    """A CSV text as the DataFrame pandas.read_csv makes of the file."""
    return pd.read_csv(io.StringIO(csv_text))


def document(json_text: str) -> dict:
    return json.loads(json_text)
