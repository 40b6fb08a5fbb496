"""The report layer: schema-2 records, Markdown, HTML, ``show`` and user reports."""
