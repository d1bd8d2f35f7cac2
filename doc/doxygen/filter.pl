#!/usr/bin/env perl
# Doxygen input filter (INPUT_FILTER of Doxyfile.in), as deal.II filters its headers: PeriDeal's
# comments name parameter entries and file names with angle brackets, <Section/Entry> and
# <directory>/<base_name>.xdmf, as the messages of the code do, also across a line break.
# Outside code spans, every angle bracket of a comment line (but the arrow ->) becomes its HTML
# entity, so that Doxygen shows it instead of taking it for an HTML tag. Code lines pass
# unchanged (templates).
use strict;
use warnings;

while (my $line = <>)
{
  if ($line =~ m{^\s*(\*|///|//!|/\*\*)})
  {
    my @parts = split /(`[^`]*`)/, $line;
    for my $part (@parts)
    {
      next if $part =~ /^`/;
      $part =~ s/</&lt;/g;
      $part =~ s/(?<!-)>/&gt;/g;
    }
    $line = join '', @parts;
  }
  print $line;
}
