#!/usr/bin/env python3
# Validates NoDL documents (YAML or JSON) against the NoDL v2 schema the way the NoDL project's
# own loader does (nodl_schema/validation.py): PyYAML reads the schema and the documents, and
# jsonschema's Draft7Validator resolves parameter.schema.yaml from a store, so that the two
# schema files stay as published. Debian: python3-jsonschema, python3-yaml (./setup.sh).
# Exit 0 when every document is valid; otherwise prints each invalid file with its errors and
# exits 1 (2 on a usage error or a missing module).
#   validate-nodl.py <schema dir with nodl.schema.yaml> <document>...
import sys
import warnings

# Newer jsonschema warns that RefResolver is deprecated; the NoDL loader uses it all the same.
warnings.simplefilter('ignore', DeprecationWarning)
try:
    import yaml
    from jsonschema import Draft7Validator, RefResolver
except ImportError as e:
    print(f'validate-nodl: {e} (install python3-jsonschema and python3-yaml)', file=sys.stderr)
    sys.exit(2)

if len(sys.argv) < 3:
    print('usage: validate-nodl.py <schema dir> <document>...', file=sys.stderr)
    sys.exit(2)



def load(path):
    with open(path, encoding='utf-8') as f:
        return yaml.safe_load(f)


schema_dir = sys.argv[1]
schema = load(f'{schema_dir}/nodl.schema.yaml')
parameter = load(f'{schema_dir}/parameter.schema.yaml')
store = {'parameter.schema.yaml': parameter, parameter.get('$id', ''): parameter}
validator = Draft7Validator(schema, resolver=RefResolver.from_schema(schema, store=store))

invalid = 0
for path in sys.argv[2:]:
    errors = sorted(validator.iter_errors(load(path)), key=lambda e: list(e.absolute_path))
    if not errors:
        continue
    invalid += 1
    print(f'{path}: invalid')
    for e in errors[:12]:
        where = '/'.join(str(p) for p in e.absolute_path)
        print(f'  #/{where}: {e.message}')
sys.exit(1 if invalid else 0)
