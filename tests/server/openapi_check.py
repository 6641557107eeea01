"""Validates API responses against the schemas of proto/openapi.yaml (python3-jsonschema)."""
import os

import jsonschema
import yaml

SPEC_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "proto", "openapi.yaml")

with open(SPEC_PATH, encoding="utf-8") as f:
    SPEC = yaml.safe_load(f)
_RESOLVER = jsonschema.RefResolver.from_schema(SPEC)


def validate(instance, schema_name):
    """Raises jsonschema.ValidationError when `instance` does not match the named schema."""
    schema = {"$ref": f"#/components/schemas/{schema_name}"}
    jsonschema.Draft202012Validator(schema, resolver=_RESOLVER).validate(instance)


def validate_inline(instance, path, method, status):
    """Validates against a response schema written inline in the path's operation."""
    content = SPEC["paths"][path][method]["responses"][str(status)]["content"]
    schema = content["application/json"]["schema"]
    jsonschema.Draft202012Validator(schema, resolver=_RESOLVER).validate(instance)
