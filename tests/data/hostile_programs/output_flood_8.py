# class: output_flood
# expect: contained
# attack: output and error made of lone surrogates: the tools' side shortens a report to 8000 and 4000 characters first and only then makes it printable, which writes each lone surrogate as a six-character \udXXX escape, so the result carries 48000 characters of output and 24000 of error (and JSON writes each backslash twice more)
names = get_object_name_list()
print(chr(0xD800) * 100_000)
raise ValueError(chr(0xDFFF) * 100_000)
